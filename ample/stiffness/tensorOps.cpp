//--------------------------------------------------------------------------
// tensorOps — small helpers between 6-vectors and 3x3 symmetric tensors
//--------------------------------------------------------------------------
// See tensorOps.h. [AMPLE] eqs 9-10 (exponential and logarithm).
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

// f(A) = V f(lambda) V' for a symmetric A. Plane strain keeps A block diagonal
// (A_xz = A_yz = 0): then the in-plane 2x2 block is decomposed in closed form and
// the zz entry is mapped directly, which gives the same tensor at a third of the cost.
InPlaneEigen inPlaneEigen(const Matrix3d& A) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es;
  es.computeDirect(A.topLeftCorner<2, 2>());
  return {es.eigenvalues(), es.eigenvectors(), A(2, 2)};
}

// n diag(d) n' in the plane, d33 out of it: the tensor with A's in-plane eigenvectors n
// and the values d, d33 (f of A's eigenvalues)
static Matrix3d fromEigen(const InPlaneEigen& e, const Eigen::Vector2d& d, double d33) {
  Matrix3d R = Matrix3d::Zero();
  R.topLeftCorner<2, 2>() = e.n * d.asDiagonal() * e.n.transpose();
  R(2, 2) = d33;
  return R;
}

Matrix3d symExp(const Matrix3d& A) {
  if (A(0, 2) == 0.0 && A(1, 2) == 0.0 && A(2, 0) == 0.0 && A(2, 1) == 0.0) {  // in plane
    const InPlaneEigen e = inPlaneEigen(A);
    return fromEigen(e, Eigen::Vector2d(std::exp(e.lam(0)), std::exp(e.lam(1))), std::exp(e.zz));
  }
  Eigen::SelfAdjointEigenSolver<Matrix3d> es(A);         // a full 3 x 3 tensor
  const Vector3d lam = es.eigenvalues();
  const Vector3d d(std::exp(lam(0)), std::exp(lam(1)), std::exp(lam(2)));
  return es.eigenvectors() * d.asDiagonal() * es.eigenvectors().transpose();
}

Matrix3d symLog(const Matrix3d& A) {
  if (A(0, 2) == 0.0 && A(1, 2) == 0.0 && A(2, 0) == 0.0 && A(2, 1) == 0.0)  // in plane
    return symLog(inPlaneEigen(A));
  Eigen::SelfAdjointEigenSolver<Matrix3d> es(A);         // a full 3 x 3 tensor
  const Vector3d lam = es.eigenvalues();
  const Vector3d d(std::log(lam(0)), std::log(lam(1)), std::log(lam(2)));
  return es.eigenvectors() * d.asDiagonal() * es.eigenvectors().transpose();
}

Matrix3d symLog(const InPlaneEigen& e) {
  return fromEigen(e, Eigen::Vector2d(std::log(e.lam(0)), std::log(e.lam(1))), std::log(e.zz));
}

Matrix3d stretchTensor(const Matrix3d& F) {
  Eigen::SelfAdjointEigenSolver<Matrix3d> es(F.transpose() * F);
  const Vector3d s = es.eigenvalues().cwiseSqrt();
  return es.eigenvectors() * s.asDiagonal() * es.eigenvectors().transpose();
}

}  // namespace ample
