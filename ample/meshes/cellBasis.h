//--------------------------------------------------------------------------
// cellBasis — basis values and gradients of one cell of a general mesh at x
//--------------------------------------------------------------------------
// docs/meshes.md. Linear triangle (nodes 0, 1, 2 anticlockwise, 2A = the
// cross product (x1 - x0) x (x2 - x0)): barycentric coordinates
//   N1 = ((x - x0) x (x2 - x0)) / 2A,  N2 = ((x1 - x0) x (x - x0)) / 2A,
//   N0 = 1 - N1 - N2,   grad Ni = [y_j - y_k; x_k - x_j] / 2A (i, j, k cyclic),
// constant in the cell. Bilinear quadrilateral (nodes anticlockwise, local
// corners xi_a = [-1 1 1 -1], eta_a = [-1 -1 1 1]):
//   N_a = (1 + xi_a xi)(1 + eta_a eta)/4,  x(xi) = sum_a N_a(xi) x_a,
// xi from x by Newton iterations on r(xi) = x(xi) - x, starting at xi = 0:
//   J = dx/dxi = sum_a x_a (dN_a/dxi)^T,  xi <- xi - J^-1 r,
// with coordinates taken about the cell's first node (so round-off is
// relative to the cell size), until |dxi|_inf <= 1e-14 (after 30 passes a
// step <= 1e-12 is taken as round-off of a distorted cell; RunError beyond that
// or when det J <= 0); then grad N_a = J^-T dN_a/dxi. A local coordinate
// within 1e-14 of a cell edge (xi = +-1; a barycentric coordinate 0) is put on
// it, so the nodes off that edge get exactly N = 0 there, as SvpMPM gives on
// the grid (dropNullNodes and detFDoFs test for exact zeros).
// Inputs:  mesh (type, coord, etpl) · cell e · x (2)
// Outputs: CellBasis: N (nen, value per local node of e) · dN (2 x nen) · xi
//          (triangles: (N1, N2)) · passes (Newton passes, 0 for triangles)
// Tests:   tests/test_mesh.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"

namespace ample {

struct CellBasis {
  std::array<double, nen> N{};                                       // N_a(x), local node a
  Eigen::Matrix<double, nD, nen> dN = Eigen::Matrix<double, nD, nen>::Zero();  // grad N_a
  Vector2d xi = Vector2d::Zero();                                    // local coordinates
  int passes = 0;                                                    // Newton passes taken
};

CellBasis cellBasis(const Mesh& mesh, int e, const Vector2d& x);
int localNode(const Mesh& mesh, int e, int node);  // a with etpl(e, a) = node, or -1

}  // namespace ample
