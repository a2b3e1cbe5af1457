//--------------------------------------------------------------------------
// inPlaneEigen — the spectral decomposition of a plane-strain tensor in closed form
//--------------------------------------------------------------------------
// In plane strain b_e and eps_e are block diagonal (no xz, yz terms): their
// in-plane 2x2 block is decomposed in closed form and the zz entry is its own
// eigenvalue. inPlaneExp / inPlaneLog give symExp / symLog (tensorOps.h) of such
// a tensor to round-off at a third of the cost (a full 3x3 tensor: symExp /
// symLog's way). The fast point loop (ample/fast/) and F-bar (ample/locking/)
// decompose the trial b_e once and take both ln(b_e) ([AMPLE] eq 10) and its
// derivative (dLogdB2D, formULstiff.h) from it.
// Inputs:  A (3x3) symmetric; inPlaneEigen and inPlaneLog(e): A_xz = A_yz = 0
// Outputs: the decomposition (lam, n, zz); exp(A), ln(A)
// Tests:   tests/test_tensorOps.cpp (against symExp, symLog)
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"

namespace ample {

struct InPlaneEigen {          // the in-plane block's eigenvalues lam and eigenvectors n (columns), the zz entry
  Eigen::Vector2d lam;
  Eigen::Matrix2d n;
  double zz;
};
InPlaneEigen inPlaneEigen(const Matrix3d& A);  // A block diagonal (A_xz = A_yz = 0)
Matrix3d inPlaneLog(const InPlaneEigen& e);    // ln(A) from A's decomposition
Matrix3d inPlaneExp(const Matrix3d& A);        // exp(A)
Matrix3d inPlaneLog(const Matrix3d& A);        // ln(A)

}  // namespace ample
