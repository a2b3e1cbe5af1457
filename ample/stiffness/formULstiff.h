//--------------------------------------------------------------------------
// formULstiff — spatial consistent tangent a_ijkl of the updated Lagrangian form
//--------------------------------------------------------------------------
// [Lagrangian] appendix A.1, eqs A.1-A.2 (used in [AMPLE] eqs 13-14):
//   a_ijkl = 1/(2J) D_ijmn L_mnpq B_pqkl - sigma_il delta_jk
//   L = d ln(b_e)/d b_e (Daleckii-Krein form of the derivative of the matrix
//   logarithm, limit 1/lambda for equal eigenvalues),
//   B_pqkl = delta_pk b_ql + delta_qk b_pl, evaluated at the trial b_e.
// Tensors are 9x9 matrices indexed by pairs (i,j) -> 3*i + j (0-based).
// Inputs:  F (3x3) · D (6x6) algorithmic tangent · sig (6) Cauchy · BeT (3x3) trial b_e
// Outputs: A (9x9) with delta sigma_ij = A(3i+j, 3k+l) d(delta u_k)/dx_l
// Tests:   tests/test_formULstiff.cpp, tests/test_detMPs.cpp (finite differences)
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"
#include "tensorOps.h"
#include <Eigen/Eigenvalues>

namespace ample {

using Matrix9d = Eigen::Matrix<double, 9, 9>;

Matrix9d dLogdB(const Matrix3d& b);  // L_ijkl = d ln(b)_ij / d b_kl
Matrix9d dLogdB(const Eigen::SelfAdjointEigenSolver<Matrix3d>& eig);  // from b's eigen-decomposition
Matrix9d formULstiff(const Matrix3d& F, const Matrix6d& D, const Vector6d& sig,
                     const Matrix3d& BeT);

// Plane strain: b_e is block diagonal (no xz, yz terms), so L and B couple the
// in-plane pairs only and the in-plane block of a_ijkl follows from 4x4 blocks,
//   A4 = 1/(2J) D4 L4 B4 - S4, pairs (i,j) -> 2*i + j with i, j in {x, y}:
// the same numbers as the in-plane block of formULstiff at a tenth of the work.
using Matrix4d = Eigen::Matrix4d;
Matrix4d formULstiff2D(const Matrix3d& F, const Matrix6d& D, const Vector6d& sig,
                       const Matrix3d& BeT);
Matrix4d formULstiff2D(const Matrix3d& F, const Matrix6d& D, const Vector6d& sig,
                       const Matrix3d& BeT, const Matrix4d& L);  // L = dLogdB2D(BeT) given
Matrix4d dLogdB2D(const Matrix3d& b);      // in-plane block of dLogdB (b block diagonal)
Matrix4d dLogdB2D(const InPlaneEigen& b);  // the same from b's decomposition (tensorOps.h)
Matrix4d elasticBlock2D(const Matrix6d& D);  // in-plane block of D as a pair tensor

}  // namespace ample
