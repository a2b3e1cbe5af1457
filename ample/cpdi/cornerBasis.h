//--------------------------------------------------------------------------
// cornerBasis — the basis of each of a point's nodes at each domain corner
//--------------------------------------------------------------------------
// [CPDI] sec 2 (iv): S(v, c) = N_nIN[v](x_c), the values SvpCPDI averages (its Sc),
// which the CPDI2 corners and the corner domain update also move with
// (ample/domains/), and the lone-node rule reads (ample/remedies/loneNodes.cpp).
// On the regular grid N is the node's bi-linear basis, the product of SvpMPM in x
// and y (gridBasis); on a general mesh (docs/meshes.md) the basis of the cell that
// holds the corner, searched once per corner (cellBasis; a corner outside the mesh:
// cornerCell's cell, its basis continued to the corner).
// Inputs:  mesh · mp (nIN, nn; mpC) · x (2 x 4 corners, domainCorners)
// Outputs: S (MAXN x 4), rows nn and beyond zero · gridBasis: N_node(x)
// Tests:   tests/test_cpdi.cpp, tests/test_updateDomain.cpp
//--------------------------------------------------------------------------
#pragma once
#include "domainCorners.h"

namespace ample {

using CornerBasis = Eigen::Matrix<double, MAXN, 4>;  // S(v, c): node v, corner c
CornerBasis cornerBasis(const Mesh& mesh, const MaterialPoint& mp, const Corners& x);
double gridBasis(const Mesh& mesh, int node, const Vector2d& x);  // bi-linear grid basis N_node(x)

}  // namespace ample
