// Tests of linSolve (seed 002 eq 29): skipped at NRit 0, prescribed
// increments at NRit 1 only, reactions, and a singular system refused.
#include "ample/errors.h"
#include "ample/linSolve.h"
#include <doctest/doctest.h>

using namespace ample;

namespace {
// a chain of 4 springs between 5 dofs (stiffness k_i = i + 1)
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
  TEST_CASE("linSolve: zero increments at NRit = 0") {
    const LinSolveOut o = linSolve({{0, 0.5}}, chain(), Eigen::VectorXd::Ones(5), 0, {1, 2, 3, 4});
    CHECK(o.duvw.norm() == 0.0);
    CHECK(o.drct.norm() == 0.0);
  }
  TEST_CASE("linSolve: prescribed increment at NRit = 1, equilibrium and reactions") {
    const SpMat K = chain();
    Eigen::VectorXd oobf = Eigen::VectorXd::Zero(5);
    oobf(4) = 2.0;  // a force at the free end
    const std::vector<BC> bc = {{0, 0.1}};
    const LinSolveOut o = linSolve(bc, K, oobf, 1, {1, 2, 3, 4});
    CHECK(o.duvw(0) == 0.1);
    const Eigen::VectorXd r = K * o.duvw - oobf;  // zero at the free dofs
    CHECK(r.tail(4).norm() <= 1e-13);
    CHECK(o.drct(0) == doctest::Approx(r(0)).epsilon(1e-13));
    CHECK(o.drct(0) == doctest::Approx(-2.0).epsilon(1e-13));  // reaction balances the load
    CHECK(o.duvw(4) - o.duvw(0) == doctest::Approx(2.0 * (1 + 1 / 2. + 1 / 3. + 1 / 4.)).epsilon(1e-13));
    const LinSolveOut o2 = linSolve(bc, K, Eigen::VectorXd::Zero(5), 2, {1, 2, 3, 4});
    CHECK(o2.duvw.norm() == 0.0);  // the prescribed increment enters once per load step
  }
  TEST_CASE("linSolve: a rigid-body mode (no constraint) is reported, not solved") {
    CHECK_THROWS_AS(linSolve({}, chain(), Eigen::VectorXd::Ones(5), 1, {0, 1, 2, 3, 4}), RunError);
  }
}
