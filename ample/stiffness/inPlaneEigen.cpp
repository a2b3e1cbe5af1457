//--------------------------------------------------------------------------
// inPlaneEigen — the spectral decomposition of a plane-strain tensor in closed form
//--------------------------------------------------------------------------
// See inPlaneEigen.h. [AMPLE] eqs 9-10 (exponential and logarithm).
//--------------------------------------------------------------------------
#include "inPlaneEigen.h"
#include <Eigen/Eigenvalues>
#include <cmath>

namespace ample {

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
  return {es.eigenvalues(), es.eigenvectors(), A(2, 2)};
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
