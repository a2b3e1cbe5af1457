//--------------------------------------------------------------------------
// tensorOps — Voigt 6-vectors and 3x3 tensors; exp and log of a symmetric tensor
//--------------------------------------------------------------------------
// See tensorOps.h. [AMPLE] eqs 9-10 (exponential and logarithm).
//--------------------------------------------------------------------------
#include "tensorOps.h"
#include <Eigen/Eigenvalues>

namespace ample {

Matrix3d strainToTensor(const Vector6d& e) {
  return (Matrix3d() << e(0), 0.5 * e(3), 0.5 * e(5), 0.5 * e(3), e(1), 0.5 * e(4), 0.5 * e(5), 0.5 * e(4), e(2)).finished();
}

Vector6d tensorToStrain(const Matrix3d& t) {
  return (Vector6d() << t(0, 0), t(1, 1), t(2, 2), 2 * t(0, 1), 2 * t(1, 2), 2 * t(2, 0)).finished();
}

Matrix3d stressToTensor(const Vector6d& s) {
  return (Matrix3d() << s(0), s(3), s(5), s(3), s(1), s(4), s(5), s(4), s(2)).finished();
}

Vector6d tensorToStress(const Matrix3d& t) {
  return (Vector6d() << t(0, 0), t(1, 1), t(2, 2), t(0, 1), t(1, 2), t(2, 0)).finished();
}

Matrix3d symExp(const Matrix3d& A) {
  const Eigen::SelfAdjointEigenSolver<Matrix3d> es(A);            // A = V diag(lam) V'
  return es.eigenvectors() * es.eigenvalues().array().exp().matrix().asDiagonal() * es.eigenvectors().transpose();
}

Matrix3d symLog(const Matrix3d& A) {
  const Eigen::SelfAdjointEigenSolver<Matrix3d> es(A);            // A = V diag(lam) V'
  return es.eigenvectors() * es.eigenvalues().array().log().matrix().asDiagonal() * es.eigenvectors().transpose();
}

Matrix3d stretchTensor(const Matrix3d& F) {
  Eigen::SelfAdjointEigenSolver<Matrix3d> es(F.transpose() * F);
  const Vector3d s = es.eigenvalues().cwiseSqrt();
  return es.eigenvectors() * s.asDiagonal() * es.eigenvectors().transpose();
}

}  // namespace ample
