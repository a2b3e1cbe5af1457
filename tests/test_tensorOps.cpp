// Tests of tensorOps: Voigt <-> tensor round trips, exponential and logarithm
// of symmetric tensors ([AMPLE] eqs 9-10), and the closed-form in-plane ones against them.
#include "ample/stiffness/tensorOps.h"
#include <doctest/doctest.h>
#include <cmath>

using namespace ample;

namespace {
Matrix3d spd() {  // a symmetric positive definite tensor with distinct eigenvalues
  Matrix3d A;
  A << 2.0, 0.3, -0.1, 0.3, 1.5, 0.2, -0.1, 0.2, 0.8;
  return A;
}
}  // namespace

TEST_SUITE("tensorOps") {
  TEST_CASE("tensorOps: strain 6-vector <-> tensor round trip / the vector carries engineering shear") {
    Vector6d v;
    v << 1, 2, 3, 4, 5, 6;
    const Matrix3d e = strainToTensor(v);
    CHECK(tensorToStrain(e) == v);
    CHECK((e - e.transpose()).norm() == 0.0);
    CHECK(e(0, 0) == 1.0);
    CHECK(e(2, 2) == 3.0);
    CHECK(e(0, 1) == 2.0);  // gamma_xy / 2
    CHECK(e(1, 2) == 2.5);  // gamma_yz / 2
    CHECK(e(2, 0) == 3.0);  // gamma_zx / 2
  }
  TEST_CASE("tensorOps: stress 6-vector <-> tensor round trip / the vector carries tensor shear") {
    Vector6d v;
    v << 1, 2, 3, 4, 5, 6;
    const Matrix3d s = stressToTensor(v);
    CHECK(tensorToStress(s) == v);
    CHECK((s - s.transpose()).norm() == 0.0);
    CHECK(s(0, 1) == 4.0);
    CHECK(s(1, 2) == 5.0);
    CHECK(s(2, 0) == 6.0);
    // work conjugacy: sigma : eps (tensors) = sigma_v . eps_v (6-vectors)
    Vector6d eps;
    eps << 0.1, -0.2, 0.3, 0.4, -0.5, 0.6;
    const double tensorWork = (stressToTensor(v).cwiseProduct(strainToTensor(eps))).sum();
    CHECK(tensorWork == doctest::Approx(v.dot(eps)).epsilon(1e-14));
  }
  TEST_CASE("tensorOps: symExp(symLog(A)) = A for SPD A and symLog(symExp(B)) = B") {
    const Matrix3d A = spd();
    CHECK((symExp(symLog(A)) - A).norm() <= 1e-13 * A.norm());
    Matrix3d B;  // any symmetric tensor, eigenvalues of either sign
    B << -0.4, 0.2, 0.1, 0.2, 0.3, -0.25, 0.1, -0.25, 0.05;
    CHECK((symLog(symExp(B)) - B).norm() <= 1e-13);
    CHECK(std::abs(symLog(A).trace() - std::log(A.determinant())) <= 1e-13);  // tr ln = ln det
  }
  TEST_CASE("tensorOps: log of a diagonal tensor / exp of zero / repeated eigenvalues") {
    const Matrix3d L = symLog(Vector3d(1.0, std::exp(2.0), std::exp(-1.0)).asDiagonal());
    CHECK((L - Matrix3d(Vector3d(0, 2, -1).asDiagonal())).norm() <= 1e-14);
    CHECK((symExp(Matrix3d::Zero()) - Matrix3d::Identity()).norm() <= 1e-15);
    CHECK(symLog(Matrix3d::Identity()).norm() <= 1e-15);
    const Matrix3d E2 = symExp(Matrix3d(Vector3d(0.5, 0.5, -0.2).asDiagonal()));
    CHECK((E2 - Matrix3d(Vector3d(std::exp(0.5), std::exp(0.5), std::exp(-0.2)).asDiagonal()))
              .norm() <= 1e-14);
  }
  TEST_CASE("tensorOps: symExp is the exponential of a rotated diagonal tensor / Q exp(L) Q'") {
    const double a = 0.7;
    Matrix3d Q;
    Q << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
    const Vector3d lam(0.3, -0.6, 1.1);
    const Matrix3d B = Q * lam.asDiagonal() * Q.transpose();
    const Matrix3d expected = Q * Vector3d(lam.array().exp()).asDiagonal() * Q.transpose();
    CHECK((symExp(B) - expected).norm() <= 1e-13 * expected.norm());
  }
  TEST_CASE("inPlaneEigen: inPlaneExp and inPlaneLog of a plane-strain tensor equal symExp and symLog to round-off / and of a full 3 x 3 one") {
    const double a = 0.4;
    Matrix3d Q = Matrix3d::Identity();                // a rotation in the plane
    Q.topLeftCorner<2, 2>() << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
    for (const Vector3d& lam : {Vector3d(0.3, -0.6, 0.1), Vector3d(0.2, 0.2, -0.05), Vector3d(1e-3, -2e-3, 5e-4)}) {
      CAPTURE(lam.transpose());
      const Matrix3d B = Q * lam.asDiagonal() * Q.transpose();      // block diagonal
      const Matrix3d expB = Q * Vector3d(lam.array().exp()).asDiagonal() * Q.transpose();
      CHECK((inPlaneExp(B) - expB).norm() <= 1e-14 * expB.norm());
      CHECK((inPlaneExp(B) - symExp(B)).norm() <= 1e-14 * expB.norm());
      CHECK((inPlaneLog(expB) - B).norm() <= 1e-14 * expB.norm());
      CHECK((inPlaneLog(inPlaneEigen(expB)) - symLog(expB)).norm() <= 1e-14 * expB.norm());
    }
    const Matrix3d A = spd();                         // not block diagonal: the full decomposition
    CHECK((inPlaneExp(inPlaneLog(A)) - A).norm() <= 1e-13 * A.norm());
    CHECK((inPlaneLog(A) - symLog(A)).norm() <= 1e-14 * A.norm());
  }

  TEST_CASE("inPlaneEigen: an eigenvalue 1e-20 of the other keeps its digits / its log is finite, as symLog's") {
    // b = [1.3 c; c t] with c = 1e-9 t: lam_min = t - c^2 / (1.3 - t) + ... = t (1 - 1e-18 t / 1.3),
    // t to 1e-15 relative; ln(lam_min) to 1e-15 absolute. The closed form alone gave 1.000000005e-8
    // for t = 1e-8, 1.1e-16 for 1e-16 and 0 for 1e-20.
    for (double t : {1e-3, 1e-8, 1e-12, 1e-16, 1e-20, 1e-200}) {
      CAPTURE(t);
      Matrix3d b = Matrix3d::Identity();
      b.topLeftCorner<2, 2>() << 1.3, 1e-9 * t, 1e-9 * t, t;
      const InPlaneEigen e = inPlaneEigen(b);
      CHECK(std::abs(e.lam(0) - t) <= 1e-15 * t);
      CHECK(std::abs(e.lam(1) - 1.3) <= 1e-15 * 1.3);
      const Matrix3d lnb = inPlaneLog(e);
      CHECK(std::abs(lnb(1, 1) - std::log(t)) <= 1e-15 * std::abs(std::log(t)));
      CHECK(std::abs(lnb(0, 0) - std::log(1.3)) <= 1e-15);
      b.topLeftCorner<2, 2>() << t, 1e-9 * t, 1e-9 * t, 1.3;     // the small one first
      CHECK(std::abs(inPlaneEigen(b).lam(0) - t) <= 1e-15 * t);
    }
    // rotated by 0.4 rad: b = Q diag(1, t) Q', whose entries carry round-off of 1e-16 and so
    // det b that of a few 1e-16; lam_min to 1e-14 and its eigenvector along Q's second column
    const double a = 0.4;
    Eigen::Matrix2d Q;
    Q << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
    for (double t : {1e-4, 1e-6, 1e-8}) {
      CAPTURE(t);
      Matrix3d b = Matrix3d::Identity();
      b.topLeftCorner<2, 2>() = Q * Eigen::Vector2d(1.0, t).asDiagonal() * Q.transpose();
      const InPlaneEigen e = inPlaneEigen(b);
      CHECK(std::abs(e.lam(0) - t) <= 1e-14);
      CHECK(std::abs(e.lam(1) - 1.0) <= 1e-14);
      CHECK(std::abs(std::abs(e.n.col(0).dot(Q.col(1))) - 1.0) <= 1e-14);
    }
  }
}
