//--------------------------------------------------------------------------
// tensorOps — Voigt 6-vectors and 3x3 tensors; exp and log of a symmetric tensor
//--------------------------------------------------------------------------
// Voigt order [xx yy zz xy yz zx]. Strain 6-vectors carry engineering shear
// (gamma = 2 eps), stress 6-vectors the tensor components. symExp/symLog are
// the exponential and logarithm of a symmetric tensor through its spectral
// decomposition A = V diag(lam) V', f(A) = V diag(f(lam)) V' ([AMPLE] eqs 9-10);
// stretchTensor the right stretch U of F = R U ([Lagrangian] eq 34).
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

}  // namespace ample
