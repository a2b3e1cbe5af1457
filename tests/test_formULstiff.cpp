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
