// Tests of formULstiff: the derivative of the matrix logarithm against finite
// differences (also with repeated eigenvalues) and the small-strain limit of
// the spatial tangent (seed 000 eqs A.1-A.2).
#include "ample/formULstiff.h"
#include "ample/tensorOps.h"
#include "constitutive/Hooke3d.h"
#include <doctest/doctest.h>

using namespace ample;

namespace {
// L applied to symmetric increments against central differences of ln(b)
double dLogError(const Matrix3d& b) {
  const Matrix9d L = dLogdB(b);
  double worst = 0;
  const double d = 1e-6;
  for (int k = 0; k < 3; ++k)
    for (int l = k; l < 3; ++l) {
      Matrix3d dB = Matrix3d::Zero();
      dB(k, l) += 0.5;
      dB(l, k) += 0.5;
      const Matrix3d fd = (symLog(b + d * dB) - symLog(b - d * dB)) / (2 * d);
      const Eigen::Matrix<double, 9, 1> Ld = L * Eigen::Map<const Eigen::Matrix<double, 9, 1>>(
                                                     Matrix3d(dB.transpose()).data());
      Matrix3d Lm;  // row-major pairs (3i + j) back to a matrix
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Lm(i, j) = Ld(3 * i + j);
      worst = std::max(worst, (Lm - fd).norm() / fd.norm());
    }
  return worst;
}
}  // namespace

TEST_SUITE("formULstiff") {
  TEST_CASE("formULstiff: d ln(b)/db equals central differences, distinct and repeated eigenvalues") {
    Matrix3d b;
    b << 1.3, 0.2, 0.0, 0.2, 0.9, 0.0, 0.0, 0.0, 1.0;
    CHECK(dLogError(b) < 1e-7);
    CHECK(dLogError(Matrix3d::Identity()) < 1e-7);
    CHECK(dLogError(Matrix3d(Vector3d(2.0, 2.0, 3.0).asDiagonal())) < 1e-7);
  }
  TEST_CASE("formULstiff: at F = I without stress the tangent is the elastic D") {
    const Matrix6d D = elasticStiffness(1e6, 0.25);
    const Matrix9d A = formULstiff(Matrix3d::Identity(), D, Vector6d::Zero(), Matrix3d::Identity());
    Matrix3d gradU;  // a displacement gradient: only its symmetric part stresses the body
    gradU << 1e-3, 4e-4, 0, -2e-4, -5e-4, 0, 0, 0, 0;
    const Matrix3d eps = 0.5 * (gradU + gradU.transpose());
    const Vector6d sig = D * tensorToStrain(eps);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double s = 0;
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) s += A(3 * i + j, 3 * k + l) * gradU(k, l);
        CHECK(s == doctest::Approx(stressToTensor(sig)(i, j)).epsilon(1e-12).scale(1e3));
      }
  }
}
