// Tests of tensorOps: Voigt <-> tensor round trips, exponential and logarithm
// of symmetric tensors (seed 002 eqs 9-10).
#include "ample/tensorOps.h"
#include <doctest/doctest.h>

using namespace ample;

TEST_SUITE("tensorOps") {
  TEST_CASE("tensorOps: strain and stress 6-vectors round trip; strain carries engineering shear") {
    Vector6d v;
    v << 1, 2, 3, 4, 5, 6;
    CHECK(tensorToStrain(strainToTensor(v)) == v);
    CHECK(tensorToStress(stressToTensor(v)) == v);
    CHECK(strainToTensor(v)(0, 1) == 2.0);  // gamma_xy / 2
    CHECK(stressToTensor(v)(0, 1) == 4.0);
    CHECK(strainToTensor(v)(2, 0) == 3.0);
  }
  TEST_CASE("tensorOps: symExp and symLog are inverse; known values") {
    Matrix3d A;
    A << 2.0, 0.3, -0.1, 0.3, 1.5, 0.2, -0.1, 0.2, 0.8;  // symmetric positive definite
    CHECK((symExp(symLog(A)) - A).norm() <= 1e-13);
    CHECK((symExp(Matrix3d::Zero()) - Matrix3d::Identity()).norm() <= 1e-15);
    const Matrix3d L = symLog(Vector3d(1.0, std::exp(2.0), std::exp(-1.0)).asDiagonal());
    CHECK((L - Matrix3d(Vector3d(0, 2, -1).asDiagonal())).norm() <= 1e-14);
    CHECK(std::abs(symLog(A).trace() - std::log(A.determinant())) <= 1e-13);
  }
}
