//--------------------------------------------------------------------------
// ibStiffness — the implicit-boundary terms K2, K3 (eqs 17-27) and f_ER (eq 28)
//--------------------------------------------------------------------------
// [Boundaries] secs 3-4. Trial u' = [D] u + u_a (eq 13), [D] the Dirichlet matrix:
//   Fixed, Prescribed:        [D] = d I                  (both directions)
//   Roller, PrescribedNormal: [D] = T' diag(d, 1) T = I - (1 - d) n n'   (eq 25, sec 3.2)
// written [D] = A + d M (A = 0, M = I; or A = I - n n', M = n n'), d of eq 16.
// For node j and direction l the strain of u' = [D] N_j e_l splits (eq 17) into
//   [B1j] e_l = eps(D e_l (x) grad N_j) = a_jl + d m_jl     (eq 19: a = A part, m = M part)
//   [B2j] e_l = eps(N_j (grad D) e_l) = d' g_jl, g_jl = eps(N_j M e_l (x) n)   (eq 20,
//               grad D_il = d' M_il n: the [D2bar][T] of eqs 26-27)
// with eps(G) = [G_xx, G_yy, G_xy + G_yx]. Across the band (n in [0, delta],
// bandIntegrals) and along the piece [r0, r1] of each CutCell (10-point Gauss,
// N_j and grad N_j taken on the boundary, phi = 0, as delta << h):
//   K2 = int_t ( int d' a'Cg + int d d' m'Cg ) dt              (eqs 21, 26)
//   K3 = int_t   int d'^2 g'Cg dt                              (eqs 22, 27)
//   K_IB = K2 + K2' + K3 (the band part of K1 is left to the points, eq 18);
//   f_IB = K_IB u_a per boundary (eq 28), u_a = s duAt(b, lstp) on the dofs of
//          its cut cells (Prescribed, PrescribedNormal; s = the step's share).
// C: the plane-strain elastic matrix of the cell, from the mean E, nu of the
// points linked to the cell (eIN, so elemMPinfo must have run); a cut cell with
// no point gives nothing (its nodes are not free dofs: detFDoFs).
// addImplicitBoundaries, called by the passTerms hook after detMPs (program/run.cpp), adds
// Kt += K_IB, fint += K_IB uvw - f_IB and returns the boundary reactions
// f_IB - K_IB uvw (the normalisation of eq 35 counts them with frct); nothing
// and zeros when there are no implicit boundaries. moveBoundaries: after a
// converged step the points of Prescribed* segments move by their du.
// Inputs:  mesh · boundaries · mpData (mCst, eIN) · lstp · s | ib · uvw
// boundaryForces: the force of each boundary on the body, from the cell terms (the
// total force: fint is that of the total stress; a footing's load, a support's reaction).
// Outputs: ImplicitBoundaries {K (nDoF x nDoF), f (nDoF), cells} | Kt, fint, reactions
// Page:    docs/implicitBoundaries.md   Tests: tests/test_ibStiffness.cpp
//--------------------------------------------------------------------------
#pragma once
#include "boundary.h"
#include "cutCells.h"
#include "ample/solver/stiffnessPattern.h"

namespace ample {

struct IbCellTerm {                    // one cut cell of one boundary
  int boundary;                        // index in the setup's boundaries
  int dofs[8];                         // the cell's dofs (node j: 2j x, 2j + 1 y)
  Eigen::Matrix<double, 8, 8> k;       // K2 + K2' + K3
  Eigen::Matrix<double, 8, 1> f;       // eq 28: k u_a
};
struct ImplicitBoundaries {
  SpMat K;            // K2 + K2' + K3 of every cut cell (empty: no boundaries)
  Eigen::VectorXd f;  // eq 28, the equivalent force of the prescribed increments
  std::vector<IbCellTerm> cells;       // the terms K and f are assembled from
};

// the 8 x 8 K2 + K2' + K3 of one cut cell (dofs: the cell's nodes, x and y) for C
Eigen::Matrix<double, 8, 8> ibCellStiffness(const Mesh& mesh, const Boundary& b, const CutCell& c,
                                            const Matrix3d& C);
// plane-strain elastic matrix in [xx, yy, xy (engineering)]
Matrix3d planeStrainC(double E, double nu);

ImplicitBoundaries ibStiffness(const Mesh& mesh, const std::vector<Boundary>& boundaries,
                               const std::vector<MaterialPoint>& mpData, int lstp, double share);
Eigen::VectorXd addImplicitBoundaries(const ImplicitBoundaries& ib, const Eigen::VectorXd& uvw,
                                      SpMat& Kt, Eigen::VectorXd& fint);
// the force each boundary exerts on the body, sum over its cut cells of f - k uvw (N per m)
std::vector<Vector2d> boundaryForces(const ImplicitBoundaries& ib, const Eigen::VectorXd& uvw,
                                     int nBoundaries);
void moveBoundaries(std::vector<Boundary>& boundaries, int lstp, double share);

}  // namespace ample
