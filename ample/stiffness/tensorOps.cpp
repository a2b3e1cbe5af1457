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

template <class Fn>
static Matrix3d symFunction(const InPlaneEigen& e, Fn f) {
  const Eigen::Vector2d d = e.lam.unaryExpr(f);
  Matrix3d R = Matrix3d::Zero();
  R.topLeftCorner<2, 2>() = e.n * d.asDiagonal() * e.n.transpose();
  R(2, 2) = f(e.zz);
  return R;
}

template <class Fn>
static Matrix3d symFunction(const Matrix3d& A, Fn f) {
  if (A(0, 2) == 0.0 && A(1, 2) == 0.0 && A(2, 0) == 0.0 && A(2, 1) == 0.0)
    return symFunction(inPlaneEigen(A), f);
  Eigen::SelfAdjointEigenSolver<Matrix3d> es(A);
  const Vector3d d = es.eigenvalues().unaryExpr(f);
  return es.eigenvectors() * d.asDiagonal() * es.eigenvectors().transpose();
}

Matrix3d symExp(const Matrix3d& A) {
  return symFunction(A, [](double x) { return std::exp(x); });
}

Matrix3d symLog(const Matrix3d& A) {
  return symFunction(A, [](double x) { return std::log(x); });
}

Matrix3d symLog(const InPlaneEigen& e) {
  return symFunction(e, [](double x) { return std::log(x); });
}

Matrix3d stretchTensor(const Matrix3d& F) {
  Eigen::SelfAdjointEigenSolver<Matrix3d> es(F.transpose() * F);
  const Vector3d s = es.eigenvalues().cwiseSqrt();
  return es.eigenvectors() * s.asDiagonal() * es.eigenvectors().transpose();
}

}  // namespace ample
