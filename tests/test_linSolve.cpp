// Tests of linSolve (seed 002 eq 29): skipped at NRit 0, prescribed
// increments at NRit 1 only, equilibrium of the free dofs, reactions, dofs
// that are neither free nor prescribed left at zero, a singular system refused.
#include "ample/errors.h"
#include "ample/linSolve.h"
#include <doctest/doctest.h>
#include <cmath>

using namespace ample;

namespace {
// a chain of 4 springs between 5 dofs, spring i (dofs i, i+1) of stiffness i + 1;
// symmetric positive semi-definite (one rigid-body mode) until a dof is held
SpMat chain() {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < 4; ++i) {
    const double k = i + 1.0;
    t.emplace_back(i, i, k);
    t.emplace_back(i + 1, i + 1, k);
    t.emplace_back(i, i + 1, -k);
    t.emplace_back(i + 1, i, -k);
  }
  SpMat K(5, 5);
  K.setFromTriplets(t.begin(), t.end());
  return K;
}
}  // namespace

TEST_SUITE("linSolve") {
  TEST_CASE("linSolve: zero increments at NRit = 0 (that pass only builds Kt)") {
    const LinSolveOut o = linSolve({{0, 0.5}}, chain(), Eigen::VectorXd::Ones(5), 0, {1, 2, 3, 4});
    REQUIRE(o.duvw.size() == 5);
    REQUIRE(o.drct.size() == 5);
    CHECK(o.duvw.norm() == 0.0);
    CHECK(o.drct.norm() == 0.0);
    // the same call at NRit = 1 does move: the prescribed 0.5 enters
    CHECK(linSolve({{0, 0.5}}, chain(), Eigen::VectorXd::Ones(5), 1, {1, 2, 3, 4}).duvw(0) == 0.5);
  }
  TEST_CASE("linSolve: at NRit = 1 the prescribed increment enters / Kff x = rhs / reactions") {
    const SpMat K = chain();
    Eigen::VectorXd oobf(5);
    oobf << 0.7, 0.5, -1.0, 0.25, 2.0;  // out-of-balance force
    const std::vector<BC> bc = {{0, 0.1}};
    const std::vector<int> fd = {1, 2, 3, 4};
    const LinSolveOut o = linSolve(bc, K, oobf, 1, fd);
    CHECK(o.duvw(0) == 0.1);
    const Eigen::VectorXd r = K * o.duvw - oobf;  // Kff x + Kfb u_b = oobf_f
    for (int d : fd) CHECK(std::abs(r(d)) <= 1e-13);
    CHECK(std::abs(o.drct(0) - r(0)) <= 1e-13);  // drct(bc) = Kt(bc,:) duvw - oobf(bc)
    for (int d : fd) CHECK(o.drct(d) == 0.0);     // reactions only at the prescribed dofs
    // analytic: the reaction balances the applied forces, and spring i carries
    // the force applied beyond it, so it stretches by (sum_{j>i} oobf_j) / k_i
    CHECK(o.drct(0) == doctest::Approx(-(oobf.sum())).epsilon(1e-13));
    double u = 0.1;
    for (int i = 0; i < 4; ++i) {
      u += oobf.tail(4 - i).sum() / (i + 1.0);
      CHECK(o.duvw(i + 1) == doctest::Approx(u).epsilon(1e-13));
    }
  }
  TEST_CASE("linSolve: at NRit = 2 the prescribed increment is zero") {
    const SpMat K = chain();
    Eigen::VectorXd oobf = Eigen::VectorXd::Zero(5);
    oobf(4) = 2.0;
    const LinSolveOut o = linSolve({{0, 0.1}}, K, oobf, 2, {1, 2, 3, 4});
    CHECK(o.duvw(0) == 0.0);
    CHECK(o.duvw(4) == doctest::Approx(2.0 * (1 + 1 / 2. + 1 / 3. + 1 / 4.)).epsilon(1e-13));
    CHECK(o.drct(0) == doctest::Approx(-2.0).epsilon(1e-13));
    CHECK(linSolve({{0, 0.1}}, K, Eigen::VectorXd::Zero(5), 2, {1, 2, 3, 4}).duvw.norm() == 0.0);
  }
  TEST_CASE("linSolve: a prescribed dof inside the chain / dofs not in fd stay zero") {
    const SpMat K = chain();
    Eigen::VectorXd oobf = Eigen::VectorXd::Zero(5);
    oobf(4) = 1.0;  // dof 4 is inactive (not in fd, no bc): its force is ignored
    oobf(0) = -3.0;
    const LinSolveOut o = linSolve({{2, -0.2}}, K, oobf, 1, {0, 1, 3});
    CHECK(o.duvw(2) == -0.2);
    CHECK(o.duvw(4) == 0.0);
    CHECK(o.drct(4) == 0.0);
    const Eigen::VectorXd r = K * o.duvw - oobf;
    for (int d : {0, 1, 3}) CHECK(std::abs(r(d)) <= 1e-13);
    // analytic: springs 0 and 1 (k = 1, 2) in series carry -3 to dof 2; spring 2
    // (k = 3) ties dof 3 to dof 2 with dof 4 held at 0 by spring 3 (k = 4)
    CHECK(o.duvw(0) == doctest::Approx(-0.2 - 3.0 * (1.0 + 0.5)).epsilon(1e-13));
    CHECK(o.duvw(3) == doctest::Approx(-0.2 * 3.0 / 7.0).epsilon(1e-13));
    CHECK(std::abs(o.drct(2) - r(2)) <= 1e-13);
  }
  TEST_CASE("linSolve: a singular Kff (rigid-body mode / no constraint) throws RunError") {
    CHECK_THROWS_AS(linSolve({}, chain(), Eigen::VectorXd::Ones(5), 1, {0, 1, 2, 3, 4}), RunError);
  }
}
