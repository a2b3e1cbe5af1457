// Tests of applyGeostatic (ample/initial/geostatic.h): the K0 initial stress of a body under
// gravity. An undisturbed layer (the compaction column: rollers on both sides, fixed base,
// elastic, gravity) started from its K0 stress stays at rest when its weight acts in full from
// the first load step: displacements below 1e-9 rho g H^2 / E (the column's settlement from
// zero stress is rho g H^2 / (2 E) for nu = 0, so 2e-9 of it) and sigma_xx / sigma_yy =
// sigma_zz / sigma_yy = K0 at every point to 1e-9 of rho g H after four load steps. The
// elastic strain is D^-1 sigma (Hooke3d of it gives sigma back); bad input names its
// parameter: no gravity, a von Mises point beyond yield (K0 and the range this body allows).
#include "ample/errors.h"
#include "ample/initial/geostatic.h"
#include "setups/program/run.h"
#include "constitutive/Hooke3d.h"
#include "testProblems.h"
#include <doctest/doctest.h>
#include <cmath>
#include <string>

using namespace ample;

namespace {
Analysis setupOf(const std::string& name, const std::vector<std::pair<std::string, double>>& set) {
  const Setup* s = findSetup(name);
  REQUIRE(s != nullptr);
  Params P = s->params();
  for (const auto& kv : set) setParam(P, kv.first, kv.second);
  return s->setupGrid(P);
}

std::string inputErrorOf(Analysis an) {
  try {
    applyGeostatic(an);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_SUITE("geostatic") {
  TEST_CASE("geostatic: elasticStrainOf is D^-1: Hooke3d of the strain gives the stress back (two materials)") {
    Vector6d sigma;
    sigma << -3.0e4, -5.0e4, -2.5e4, 1.2e4, -0.7e4, 0.4e4;
    for (const MaterialConstants& mCst : {MaterialConstants{1e7, 0.3, 0}, MaterialConstants{2e5, 0.0, 0}}) {
      const Vector6d eps = elasticStrainOf(sigma, mCst.E, mCst.nu);
      CHECK((Hooke3d(eps, mCst).Ksig - sigma).norm() <= 1e-12 * sigma.norm());
    }
  }

  TEST_CASE("geostatic: the compaction column started from its K0 stress stays at rest, sigma_h / sigma_v = K0") {
    const double rho = 80, g = 10, H = 50, E = 10e3, K0 = 0.5;
    for (int mpType : {1, 2}) {                                  // MPM, GIMP
      CAPTURE(mpType);
      Analysis an = setupOf("compaction", {{"nelsy", 16}, {"lstps", 4}, {"mpType", mpType},
                                           {"geostatic", 1}, {"K0", K0}});
      REQUIRE(an.geostatic);
      applyGeostatic(an);
      for (const MaterialPoint& mp : an.mpData) {                // the start: eq 36 with K0
        const double d = H - mp.X0(1);
        CHECK(mp.sig(1) == doctest::Approx(-rho * g * d).epsilon(1e-12));
        CHECK(mp.sig(0) == doctest::Approx(K0 * mp.sig(1)).epsilon(1e-12));
      }
      RunLog log;
      solveRun(an, log);
      REQUIRE(log.converged);
      REQUIRE(log.lastConverged == 4);
      double uMax = 0, ratioErr = 0;
      for (const MaterialPoint& mp : an.mpData) {
        uMax = std::max(uMax, mp.u.norm());
        ratioErr = std::max({ratioErr, std::abs(mp.sig(0) - K0 * mp.sig(1)), std::abs(mp.sig(2) - K0 * mp.sig(1))});
      }
      const double uScale = rho * g * H * H / E;                 // 2 x the settlement from zero stress
      MESSAGE("mpType " << mpType << ": max |u| / (rho g H^2 / E) = " << uMax / uScale
              << ", max |sigma_h - K0 sigma_v| / (rho g H) = " << ratioErr / (rho * g * H));
      CHECK(uMax <= 1e-9 * uScale);
      CHECK(ratioErr <= 1e-9 * rho * g * H);
    }
  }

  TEST_CASE("geostatic: without the K0 start the same column settles rho g H^2 / (2 E) at its top (the scale of the test above)") {
    const double rho = 80, g = 10, H = 50;
    RunLog log;
    const Analysis an = testing::runSetup("compaction", {{"nelsy", 16}, {"lstps", 4}, {"E", 1e9}}, log);  // small strain
    REQUIRE(log.converged);
    double uTop = 0;
    for (const MaterialPoint& mp : an.mpData) uTop = std::max(uTop, std::abs(mp.u(1)));
    CHECK(uTop == doctest::Approx(rho * g * H * H / (2 * 1e9)).epsilon(0.02));
  }

  TEST_CASE("geostatic: bad input names its parameter: no gravity, a von Mises point beyond yield") {
    CHECK(inputErrorOf(setupOf("squeeze", {{"geostatic", 1}})).find("geostatic=on") != std::string::npos);
    // collapse: 8 m of 10 kN/m3, rho_y = 20 kPa: the deepest points (d = 7.83 m, 3 x 3 points per
    // 1 m cell) allow |1 - K0| <= 20e3 / (sqrt(2/3) 10e3 7.8333) = 0.3127, by hand
    const std::string msg = inputErrorOf(setupOf("collapse", {{"geostatic", 1}, {"K0", 0.5}}));
    CAPTURE(msg);
    CHECK(msg.find("K0=0.5") != std::string::npos);
    CHECK(msg.find("[0.6873, 1.313]") != std::string::npos);
    CHECK(inputErrorOf(setupOf("collapse", {{"geostatic", 1}, {"K0", 0.7}})).empty());
  }
}
