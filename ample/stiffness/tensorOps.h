//--------------------------------------------------------------------------
// tensorOps — Voigt 6-vectors and 3x3 tensors; exp and log of a symmetric tensor
//--------------------------------------------------------------------------
// Voigt order [xx yy zz xy yz zx]. Strain 6-vectors carry engineering shear
// (gamma = 2 eps), stress 6-vectors the tensor components. symExp/symLog are
// the exponential and logarithm of a symmetric tensor through its spectral
// decomposition A = V diag(lam) V', f(A) = V diag(f(lam)) V' ([AMPLE] eqs 9-10);
// stretchTensor the right stretch U of F = R U ([Lagrangian] eq 34). inPlaneEigen: the same
// decomposition of a plane-strain tensor in closed form (its in-plane 2x2 block, zz its own
// eigenvalue; the smaller eigenvalue as det over the larger, which keeps its digits at any
// ratio), which formULstiff's dLogdB2D and the fast loop's exp/log use.
// Inputs/outputs: 6-vectors and 3x3 matrices as named.
// Tests:   tests/test_tensorOps.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"

namespace ample {

Matrix3d strainToTensor(const Vector6d& eps);  // 6 (engineering shear) -> 3x3
Vector6d tensorToStrain(const Matrix3d& e);    // 3x3 -> 6 (engineering shear)
Matrix3d stressToTensor(const Vector6d& sig);  // 6 -> 3x3
Vector6d tensorToStress(const Matrix3d& s);    // 3x3 -> 6
Matrix3d symExp(const Matrix3d& A);            // exp of a symmetric tensor
Matrix3d symLog(const Matrix3d& A);            // log of a symmetric positive definite tensor
Matrix3d stretchTensor(const Matrix3d& F);     // U = sqrt(F'F), the right stretch tensor

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
