// Tests of formULstiff ([Lagrangian] appendix A.1, eqs A.1-A.2): the derivative of
// the matrix logarithm dLogdB against central differences of symLog (distinct,
// repeated and nearly repeated eigenvalues) and analytic limits of the spatial
// tangent a_ijkl at F = I. Tensors are 9x9 matrices, pair (i,j) -> 3i + j.
#include "ample/stiffness/formULstiff.h"
#include "ample/stiffness/tensorOps.h"
#include "constitutive/Hooke3d.h"
#include <doctest/doctest.h>
#include <cmath>

using namespace ample;

namespace {
using Vector9d = Eigen::Matrix<double, 9, 1>;

Vector9d vec(const Matrix3d& A) {  // pair (i,j) -> 3i + j
  Vector9d v;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) v(3 * i + j) = A(i, j);
  return v;
}

// worst relative error of L vec(dB) against central differences of vec(ln b),
// over the six symmetric directions dB = (e_k e_l' + e_l e_k') / 2
double dLogError(const Matrix3d& b) {
  const Matrix9d L = dLogdB(b);
  const double d = 1e-6;
  double worst = 0;
  for (int k = 0; k < 3; ++k)
    for (int l = k; l < 3; ++l) {
      Matrix3d dB = Matrix3d::Zero();
      dB(k, l) += 0.5;
      dB(l, k) += 0.5;
      const Vector9d fd = vec(symLog(b + d * dB) - symLog(b - d * dB)) / (2 * d);
      worst = std::max(worst, (L * vec(dB) - fd).norm() / fd.norm());
    }
  return worst;
}

Matrix3d rotation(double a, double b) {  // about z by a, then about x by b
  Matrix3d Rz, Rx;
  Rz << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  Rx << 1, 0, 0, 0, std::cos(b), -std::sin(b), 0, std::sin(b), std::cos(b);
  return Rx * Rz;
}

// c_ij = a_ijkl g_kl
Matrix3d contract(const Matrix9d& A, const Matrix3d& g) {
  Matrix3d c = Matrix3d::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) c(i, j) += A(3 * i + j, 3 * k + l) * g(k, l);
  return c;
}

Matrix3d gradU() {  // a small displacement gradient, not symmetric
  Matrix3d g;
  g << 1e-3, 4e-4, 0, -2e-4, -5e-4, 0, 0, 0, 0;
  return g;
}
}  // namespace

TEST_SUITE("formULstiff") {
  TEST_CASE("dLogdB: equals central differences of symLog / distinct eigenvalues") {
    Matrix3d b;
    b << 1.3, 0.2, 0.0, 0.2, 0.9, 0.0, 0.0, 0.0, 1.0;
    CHECK(dLogError(b) < 1e-6);
    const Matrix3d Q = rotation(0.4, -0.9);  // a full 3D one
    CHECK(dLogError(Q * Vector3d(0.7, 1.4, 2.3).asDiagonal() * Q.transpose()) < 1e-6);
  }
  TEST_CASE("dLogdB: equals central differences with two or three equal eigenvalues") {
    CHECK(dLogError(Matrix3d::Identity()) < 1e-6);
    CHECK(dLogError(Matrix3d(Vector3d(2.0, 2.0, 3.0).asDiagonal())) < 1e-6);
    const Matrix3d Q = rotation(0.4, -0.9);  // repeated pair in rotated axes
    CHECK(dLogError(Q * Vector3d(1.5, 1.5, 0.6).asDiagonal() * Q.transpose()) < 1e-6);
    // nearly repeated: (ln a - ln b)/(a - b) must not lose its digits as a -> b
    CHECK(dLogError(Q * Vector3d(1.5, 1.5 * (1 + 1e-11), 0.6).asDiagonal() * Q.transpose()) < 1e-6);
  }
  TEST_CASE("dLogdB: at b = I it is the identity on symmetric increments") {
    Matrix3d dB;
    dB << 0.3, -0.1, 0.2, -0.1, 0.5, 0.05, 0.2, 0.05, -0.4;
    CHECK((dLogdB(Matrix3d::Identity()) * vec(dB) - vec(dB)).norm() <= 1e-14);
  }
  TEST_CASE("formULstiff: at F = I without stress the tangent gives D : eps (small strain)") {
    const Matrix6d D = elasticStiffness(1e6, 0.25);
    const Matrix9d A = formULstiff(Matrix3d::Identity(), D, Vector6d::Zero(), Matrix3d::Identity());
    const Matrix3d g = gradU();  // only its symmetric part stresses the body
    const Matrix3d expected = stressToTensor(D * tensorToStrain(0.5 * (g + g.transpose())));
    CHECK((contract(A, g) - expected).norm() <= 1e-12 * expected.norm());
  }
  TEST_CASE("formULstiff: with an initial stress the tangent adds -sigma_il delta_jk") {
    const Matrix6d D = elasticStiffness(1e6, 0.25);
    Vector6d sig;
    sig << 3e3, -1e3, 2e3, 5e2, -4e2, 1e2;
    const Matrix9d A = formULstiff(Matrix3d::Identity(), D, sig, Matrix3d::Identity());
    const Matrix3d g = gradU();
    // a_ijkl g_kl = (D : sym g)_ij - sigma_il g_jl
    const Matrix3d expected = stressToTensor(D * tensorToStrain(0.5 * (g + g.transpose()))) -
                              stressToTensor(sig) * g.transpose();
    CHECK((contract(A, g) - expected).norm() <= 1e-12 * expected.norm());
  }
  TEST_CASE("formULstiff: the material part carries the factor 1/J") {
    const Matrix6d D = elasticStiffness(1e6, 0.25);
    const Matrix3d F = Vector3d(1.2, 0.9, 1.0).asDiagonal();  // J = 1.08
    const Matrix9d A1 = formULstiff(Matrix3d::Identity(), D, Vector6d::Zero(), Matrix3d::Identity());
    const Matrix9d AJ = formULstiff(F, D, Vector6d::Zero(), Matrix3d::Identity());
    CHECK((AJ * 1.08 - A1).norm() <= 1e-12 * A1.norm());
    // at F = b_e = I, no stress: 1/2 D L B = D (L = I, B = 2 I on symmetric pairs), so
    // a_xxxx = D(0, 0) = E (1 - nu) / ((1 + nu)(1 - 2 nu)) = 1.2e6 Pa and a_xyxy = G = 4e5 Pa
    CHECK(std::abs(A1(0, 0) - 1.2e6) <= 1e-6);
    CHECK(std::abs(A1(1, 1) - 4e5) <= 1e-6);
    CHECK(std::abs(AJ(0, 0) - 1.2e6 / 1.08) <= 1e-6);
  }
}

TEST_SUITE("formULstiff") {
  TEST_CASE("formULstiff2D: equals the in-plane block of formULstiff in plane strain") {
    Matrix3d F, BeT;  // block diagonal, as plane strain keeps them
    F << 1.2, 0.3, 0, -0.1, 0.9, 0, 0, 0, 1;
    BeT << 1.4, 0.25, 0, 0.25, 0.8, 0, 0, 0, 1.1;
    Vector6d sig;
    sig << 3e3, -2e3, 5e2, 1.5e3, 0, 0;
    for (const Matrix6d& D : {elasticStiffness(1e6, 0.3), Matrix6d(elasticStiffness(2e5, 0.1) * 0.7)}) {
      const Matrix9d A9 = formULstiff(F, D, sig, BeT);
      const Eigen::Matrix4d A4 = formULstiff2D(F, D, sig, BeT);
      for (int p = 0; p < 4; ++p)
        for (int q = 0; q < 4; ++q)
          CHECK(std::abs(A4(p, q) - A9(3 * (p / 2) + p % 2, 3 * (q / 2) + q % 2)) <= 1e-10 * A9.norm());
    }
    const Matrix3d iso = Matrix3d::Identity() * 1.3;  // repeated in-plane eigenvalues
    const Eigen::Matrix4d A4 = formULstiff2D(F, elasticStiffness(1e6, 0.3), sig, iso);
    const Matrix9d A9 = formULstiff(F, elasticStiffness(1e6, 0.3), sig, iso);
    CHECK(std::abs(A4(0, 0) - A9(0, 0)) <= 1e-10 * A9.norm());
    CHECK(std::abs(A4(1, 2) - A9(1, 3)) <= 1e-10 * A9.norm());
    // closed form at F = b_e = I: A4 = D4 - sigma_il delta_jk, e.g. a_xxxx = lambda + 2G - sigma_xx
    // (E = 1e6, nu = 0.3: 1346153.846153846 Pa), a_xyyx = G - sigma_xx... (i x, j y, k y, l x):
    // D_xyyx = G = 384615.3846153846, minus sigma_il delta_jk = sigma_xx = 3e3
    const Eigen::Matrix4d AI = formULstiff2D(Matrix3d::Identity(), elasticStiffness(1e6, 0.3), sig,
                                             Matrix3d::Identity());
    CHECK(std::abs(AI(0, 0) - (1346153.846153846 - 3e3)) <= 1e-6);
    CHECK(std::abs(AI(1, 2) - (384615.3846153846 - 3e3)) <= 1e-6);
  }
}

// The tangent against closed forms that need no other exercise: D written out by hand (an
// anisotropic one with normal-shear couplings and an isotropic one), b_e diagonal so that
// L = d ln(b)/db is the divided difference theta_mn = (ln b_m - ln b_n) / (b_m - b_n) on
// each pair (1 / b_m when equal) and B g = g b + b g', and rotations for the general b_e.
TEST_SUITE("formULstiff") {
  Matrix6d anisoD() {  // symmetric, positive definite, every entry set
    Matrix6d D;
    D << 9.0, 2.0, 1.5, 0.4, -0.3, 0.2,
         2.0, 7.0, 1.2, -0.5, 0.6, 0.1,
         1.5, 1.2, 8.0, 0.3, 0.2, -0.4,
         0.4, -0.5, 0.3, 3.0, 0.25, -0.2,
         -0.3, 0.6, 0.2, 0.25, 2.5, 0.15,
         0.2, 0.1, -0.4, -0.2, 0.15, 2.8;
    return D * 1e5;
  }
  Matrix6d isotropicD(double lam, double mu) {
    Matrix6d D = Matrix6d::Zero();
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) D(i, j) = lam;
      D(i, i) = lam + 2 * mu;
      D(i + 3, i + 3) = mu;
    }
    return D;
  }
  Matrix3d sym3(const Vector6d& s) {  // a stress 6-vector [xx yy zz xy yz zx] as a tensor
    Matrix3d t;
    t << s(0), s(3), s(5), s(3), s(1), s(4), s(5), s(4), s(2);
    return t;
  }
  Vector6d engineering(const Matrix3d& w) {  // a symmetric tensor as a strain 6-vector
    Vector6d e;
    e << w(0, 0), w(1, 1), w(2, 2), 2 * w(0, 1), 2 * w(1, 2), 2 * w(2, 0);
    return e;
  }
  // a_ijkl g_kl = 1/(2J) D_ijmn theta_mn (b_n g_mn + b_m g_nm) - sigma_il g_jl, b_e = diag(b)
  Matrix3d closedForm(double J, const Matrix6d& D, const Vector6d& sig, const Vector3d& b, const Matrix3d& g) {
    Matrix3d w;
    for (int m = 0; m < 3; ++m)
      for (int n = 0; n < 3; ++n) {
        const double th = b(m) == b(n) ? 1.0 / b(m) : std::log1p((b(m) - b(n)) / b(n)) / (b(m) - b(n));
        w(m, n) = th * (b(n) * g(m, n) + b(m) * g(n, m));
      }
    return sym3(D * engineering(w)) / (2 * J) - sym3(sig) * g.transpose();
  }
  Eigen::Vector4d vec2(const Matrix3d& g) { return Eigen::Vector4d(g(0, 0), g(0, 1), g(1, 0), g(1, 1)); }
  Matrix3d inPlane(const Eigen::Vector4d& c) {
    Matrix3d t = Matrix3d::Zero();
    t << c(0), c(1), 0, c(2), c(3), 0, 0, 0, 0;
    return t;
  }
  Matrix3d grad2() {  // an in-plane displacement gradient, not symmetric
    Matrix3d g = Matrix3d::Zero();
    g << 2e-3, -7e-4, 0, 1.1e-3, -1.3e-3, 0, 0, 0, 0;
    return g;
  }
  Matrix3d grad3() {  // a full one
    Matrix3d g;
    g << 2e-3, -7e-4, 4e-4, 1.1e-3, -1.3e-3, 6e-4, -9e-4, 3e-4, 8e-4;
    return g;
  }

  TEST_CASE("formULstiff: at F = b_e = I the tangent gives a : g = D : sym(g) - sigma g' for two hand-written D and two stresses (no Hooke3d)") {
    Vector6d s1, s2;
    s1 << 3e3, -1e3, 2e3, 5e2, -4e2, 1e2;
    s2 << -8e2, 4e3, -1.5e3, -2e3, 7e2, 1.2e3;
    for (const Matrix6d& D : {anisoD(), isotropicD(4e5, 2.5e5), anisoD()})
      for (const Vector6d& sig : {Vector6d(Vector6d::Zero()), s1, s2}) {
        const Matrix3d g = grad3();
        const Matrix3d expected = sym3(D * engineering(0.5 * (g + g.transpose()))) - sym3(sig) * g.transpose();
        const Matrix9d A = formULstiff(Matrix3d::Identity(), D, sig, Matrix3d::Identity());
        CHECK((contract(A, g) - expected).norm() <= 1e-12 * expected.norm());
        const Eigen::Matrix4d A4 = formULstiff2D(Matrix3d::Identity(), D, sig, Matrix3d::Identity());
        const Matrix3d e2 = closedForm(1.0, D, sig, Vector3d::Ones(), grad2());
        CHECK((A4 * vec2(grad2()) - vec2(e2)).norm() <= 1e-12 * e2.norm());
      }
  }
  TEST_CASE("formULstiff: diagonal b_e (distinct / repeated / nearly repeated eigenvalues) and two F: the closed form of L and B") {
    Matrix3d F1, F2;  // only J = det F enters
    F1 << 1.1, 0.2, 0, -0.1, 0.95, 0, 0, 0, 1.05;
    F2 << 0.8, -0.3, 0, 0.25, 1.3, 0, 0, 0, 0.9;
    Vector6d sig;
    sig << 2e3, -3e3, 1e3, 1.5e3, -6e2, 9e2;
    for (const Vector3d& b : {Vector3d(1.3, 0.8, 1.1), Vector3d(1.2, 1.2, 0.9), Vector3d(0.7, 0.7 * (1 + 1e-10), 1.6)})
      for (const Matrix3d& F : {F1, F2})
        for (const Matrix6d& D : {anisoD(), isotropicD(6e5, 1.5e5)}) {
          CAPTURE(b.transpose());
          const double J = F.determinant();
          const Matrix3d B = b.asDiagonal();
          const Matrix3d e3 = closedForm(J, D, sig, b, grad3());
          CHECK((contract(formULstiff(F, D, sig, B), grad3()) - e3).norm() <= 1e-8 * e3.norm());
          const Matrix3d e2 = closedForm(J, D, sig, b, grad2());
          CHECK((formULstiff2D(F, D, sig, B) * vec2(grad2()) - vec2(e2)).norm() <= 1e-8 * e2.norm());
        }
  }
  TEST_CASE("formULstiff: objective: F and b_e and sigma rotated by Q give the tangent rotated by Q (isotropic D / 3D and in plane)") {
    const Matrix6d D = isotropicD(4e5, 2.5e5);
    Matrix3d F;
    F << 1.15, 0.1, 0, -0.2, 0.9, 0, 0, 0, 1.0;
    const Vector3d b(1.25, 0.85, 1.05);
    Vector6d sig;
    sig << 2e3, -3e3, 1e3, 1.5e3, 0, 0;
    const Matrix3d B = b.asDiagonal(), S = sym3(sig);
    for (double a : {0.4, -1.1}) {
      // in plane (about z): the 2D block, b_e with off-diagonal xy terms
      Matrix3d Q;
      Q << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
      const Matrix3d BR = Q * B * Q.transpose(), SR = Q * S * Q.transpose();
      const Vector6d sigR = (Vector6d() << SR(0, 0), SR(1, 1), SR(2, 2), SR(0, 1), SR(1, 2), SR(2, 0)).finished();
      const Matrix3d g = grad2(), gR = Q * g * Q.transpose();
      const Matrix3d c = closedForm(F.determinant(), D, sig, b, g);        // unrotated, by hand
      const Eigen::Vector4d c2 = formULstiff2D(Q * F, D, sigR, BR) * vec2(gR);
      CHECK((inPlane(c2) - (Q * c * Q.transpose())).topLeftCorner<2, 2>().norm() <= 1e-8 * c.norm());
      // in 3D: about z and x
      Matrix3d Rx;
      Rx << 1, 0, 0, 0, std::cos(0.7 * a), -std::sin(0.7 * a), 0, std::sin(0.7 * a), std::cos(0.7 * a);
      const Matrix3d Q3 = Rx * Q, B3 = Q3 * B * Q3.transpose(), S3 = Q3 * S * Q3.transpose();
      const Vector6d sig3 = (Vector6d() << S3(0, 0), S3(1, 1), S3(2, 2), S3(0, 1), S3(1, 2), S3(2, 0)).finished();
      const Matrix3d h = grad3(), c3 = closedForm(F.determinant(), D, sig, b, h);
      const Matrix3d r3 = contract(formULstiff(Q3 * F, D, sig3, B3), Q3 * h * Q3.transpose());
      CHECK((r3 - Q3 * c3 * Q3.transpose()).norm() <= 1e-8 * c3.norm());
    }
  }
}
