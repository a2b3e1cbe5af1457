//--------------------------------------------------------------------------
// tensorOps — small helpers between 6-vectors and 3x3 symmetric tensors
//--------------------------------------------------------------------------
// See tensorOps.h. Seed 002 eqs 9-10 (exponential and logarithm).
//--------------------------------------------------------------------------
#include "tensorOps.h"
#include <Eigen/Eigenvalues>
#include <cmath>

namespace ample {

Matrix3d strainToTensor(const Vector6d& e) {
  Matrix3d t;
  t << e(0), 0.5 * e(3), 0.5 * e(5),
       0.5 * e(3), e(1), 0.5 * e(4),
       0.5 * e(5), 0.5 * e(4), e(2);
  return t;
}

Vector6d tensorToStrain(const Matrix3d& t) {
  Vector6d e;
  e << t(0, 0), t(1, 1), t(2, 2), 2 * t(0, 1), 2 * t(1, 2), 2 * t(2, 0);
  return e;
}

Matrix3d stressToTensor(const Vector6d& s) {
  Matrix3d t;
  t << s(0), s(3), s(5),
       s(3), s(1), s(4),
       s(5), s(4), s(2);
  return t;
}

Vector6d tensorToStress(const Matrix3d& t) {
  Vector6d s;
  s << t(0, 0), t(1, 1), t(2, 2), t(0, 1), t(1, 2), t(2, 0);
  return s;
}

Matrix3d symExp(const Matrix3d& A) {
  Eigen::SelfAdjointEigenSolver<Matrix3d> es(A);
  const Vector3d d = es.eigenvalues().array().exp();
  return es.eigenvectors() * d.asDiagonal() * es.eigenvectors().transpose();
}

Matrix3d symLog(const Matrix3d& A) {
  Eigen::SelfAdjointEigenSolver<Matrix3d> es(A);
  const Vector3d d = es.eigenvalues().array().log();
  return es.eigenvectors() * d.asDiagonal() * es.eigenvectors().transpose();
}

}  // namespace ample
