//--------------------------------------------------------------------------
// tensorOps — Voigt 6-vectors and 3x3 tensors; exp and log of a symmetric tensor
//--------------------------------------------------------------------------
// See tensorOps.h. [AMPLE] eqs 9-10 (exponential and logarithm).
//--------------------------------------------------------------------------
#include "tensorOps.h"
#include <cmath>
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

namespace {
// n diag(d) n' in the plane, d33 out of it: the tensor with A's in-plane eigenvectors n
// and the values d, d33 (f of A's eigenvalues)
Matrix3d fromEigen(const InPlaneEigen& e, const Eigen::Vector2d& d, double d33) {
  Matrix3d R = Matrix3d::Zero();
  R.topLeftCorner<2, 2>() = e.n * d.asDiagonal() * e.n.transpose();
  R(2, 2) = d33;
  return R;
}

bool inPlane(const Matrix3d& A) { return A(0, 2) == 0.0 && A(1, 2) == 0.0 && A(2, 0) == 0.0 && A(2, 1) == 0.0; }
}  // namespace

InPlaneEigen inPlaneEigen(const Matrix3d& A) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es;
  es.computeDirect(A.topLeftCorner<2, 2>());
  Eigen::Vector2d lam = es.eigenvalues();
  // The closed form finds the root of smaller size as a difference of two of the larger's size,
  // and keeps none of its digits once it is 1e-16 of the other (a column compressed to 1e-8 of
  // its height: 0 or negative, its log not finite, where symLog's iterations keep it). The
  // product of the roots, det A, keeps them: the smaller is det A over the larger.
  const int big = std::abs(lam(1)) >= std::abs(lam(0)) ? 1 : 0;
  if (std::abs(lam(1 - big)) < 1e-3 * std::abs(lam(big)))
    lam(1 - big) = (A(0, 0) * A(1, 1) - A(0, 1) * A(1, 0)) / lam(big);
  return {lam, es.eigenvectors(), A(2, 2)};
}

Matrix3d inPlaneLog(const InPlaneEigen& e) {
  return fromEigen(e, Eigen::Vector2d(std::log(e.lam(0)), std::log(e.lam(1))), std::log(e.zz));
}

Matrix3d inPlaneExp(const Matrix3d& A) {
  if (!inPlane(A)) {                                       // a full 3 x 3 tensor
    Eigen::SelfAdjointEigenSolver<Matrix3d> es(A);
    const Vector3d lam = es.eigenvalues();
    const Vector3d d(std::exp(lam(0)), std::exp(lam(1)), std::exp(lam(2)));
    return es.eigenvectors() * d.asDiagonal() * es.eigenvectors().transpose();
  }
  const InPlaneEigen e = inPlaneEigen(A);
  return fromEigen(e, Eigen::Vector2d(std::exp(e.lam(0)), std::exp(e.lam(1))), std::exp(e.zz));
}

Matrix3d inPlaneLog(const Matrix3d& A) {
  if (!inPlane(A)) {                                       // a full 3 x 3 tensor
    Eigen::SelfAdjointEigenSolver<Matrix3d> es(A);
    const Vector3d lam = es.eigenvalues();
    const Vector3d d(std::log(lam(0)), std::log(lam(1)), std::log(lam(2)));
    return es.eigenvectors() * d.asDiagonal() * es.eigenvectors().transpose();
  }
  return inPlaneLog(inPlaneEigen(A));
}


}  // namespace ample
