// Tests of the main loop (ample.cpp) on the paper's problems: Newton-Raphson
// convergence order, compaction convergence with refinement, collapse extents
// of [AMPLE] table 5, and a patch test through the whole loop.
#include "setups/program/run.h"
#include "testProblems.h"
#include <doctest/doctest.h>
#include <algorithm>
#include <array>
#include <cmath>

using namespace ample;

namespace {
using testing::runSetup;

double result(const std::string& name, const Analysis& an,
              const std::vector<std::pair<std::string, double>>& set, const std::string& key) {
  const Setup* s = findSetup(name);
  Params P = s->params();
  for (const auto& kv : set) setParam(P, kv.first, kv.second);
  for (const auto& r : s->results(an, P))
    if (r.first == key) return r.second;
  FAIL("no result " << key);
  return 0;
}

// Independent references: written here from closed forms, sharing no
// code with Hooke3d, VMconst, symLog or setups/homogeneous.cpp. Voigt order of the
// stress [xx yy zz xy yz zx]; plane strain; Lame constants from E and nu.
double lameLambda(double E, double nu) { return E * nu / ((1 + nu) * (1 - 2 * nu)); }
double lameMu(double E, double nu) { return E / (2 * (1 + nu)); }

// Hencky strain eps = ln(b)/2 of simple shear F = [1 g; 0 1] (g != 0) from the closed-form
// eigen-decomposition of the 2x2 b = F F' = [1+g^2 g; g 1]: returns {eps_xx, eps_yy, eps_xy}
std::array<double, 3> henckySimpleShear(double g) {
  const double a = 1 + g * g, c = g, d = 1;                  // b = [a c; c d]
  const double m = 0.5 * (a + d), r = std::sqrt(0.25 * (a - d) * (a - d) + c * c);
  const double l1 = m + r, l2 = m - r;                        // eigenvalues of b
  double vx = l1 - d, vy = c;                                 // eigenvector of l1
  const double n = std::sqrt(vx * vx + vy * vy);
  vx /= n;
  vy /= n;
  const double e1 = 0.5 * std::log(l1), e2 = 0.5 * std::log(l2);
  return {e2 + (e1 - e2) * vx * vx, e2 + (e1 - e2) * vy * vy, (e1 - e2) * vx * vy};
}

// Kirchhoff (= Cauchy, J = 1) stress of elastic simple shear: tau = lambda tr(eps) I + 2 mu eps
Vector6d shearStressClosedForm(double g, double E, double nu) {
  const auto e = henckySimpleShear(g);
  const double lam = lameLambda(E, nu), mu = lameMu(E, nu), tr = e[0] + e[1];  // eps_zz = 0
  Vector6d t;
  t << lam * tr + 2 * mu * e[0], lam * tr + 2 * mu * e[1], lam * tr, 2 * mu * e[2], 0, 0;
  return t;
}

// von Mises radius rho = sqrt(2 J2) = sqrt(s:s), s the deviator (tensor shear counted twice)
double vonMisesRho(const Vector6d& s) {
  const double p = (s(0) + s(1) + s(2)) / 3;
  return std::sqrt((s(0) - p) * (s(0) - p) + (s(1) - p) * (s(1) - p) + (s(2) - p) * (s(2) - p) +
                   2 * (s(3) * s(3) + s(4) * s(4) + s(5) * s(5)));
}

// Plane-strain stretch with a free top, von Mises perfect plasticity: the principal axes
// stay x, y, z, so Hencky strains add and the return is radial in principal space. Step k
// stretches x to (L0 + k du) / L0; the step's vertical log stretch dy is found by
// bisection so that tau_yy = 0. Returns tau_xx after each step.
std::vector<double> stretchClosedForm(int n, double L0, double du, double E, double nu, double rhoY) {
  const double K = E / (3 * (1 - 2 * nu)), G = lameMu(E, nu);
  std::array<double, 3> ee = {0, 0, 0};  // converged elastic log strains
  std::vector<double> tx;
  auto update = [&](double dx, double dy, std::array<double, 3>& e) {  // returns tau
    const std::array<double, 3> t = {e[0] + dx, e[1] + dy, e[2]};    // trial, d eps_zz = 0
    const double v = (t[0] + t[1] + t[2]) / 3;
    std::array<double, 3> s = {2 * G * (t[0] - v), 2 * G * (t[1] - v), 2 * G * (t[2] - v)};
    const double rho = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    const double f = rho > rhoY ? rhoY / rho : 1.0;
    std::array<double, 3> tau;
    for (int i = 0; i < 3; ++i) {
      s[i] *= f;
      tau[i] = 3 * K * v + s[i];
      e[i] = v + s[i] / (2 * G);  // the elastic strain of the returned stress
    }
    return tau;
  };
  for (int k = 1; k <= n; ++k) {
    const double dx = std::log((L0 + k * du) / (L0 + (k - 1) * du));
    double lo = -1, hi = 1;
    for (int it = 0; it < 200; ++it) {
      std::array<double, 3> e = ee;
      const double dy = 0.5 * (lo + hi);
      (update(dx, dy, e)[1] > 0 ? hi : lo) = dy;
    }
    tx.push_back(update(dx, 0.5 * (lo + hi), ee)[0]);
  }
  return tx;
}
}  // namespace

TEST_SUITE("ample") {
  TEST_CASE("ample: Newton-Raphson converges quadratically on a plastic collapse load step") {
    RunLog log;
    runSetup("collapse", {{"lstps", 40}, {"a", 2}, {"mp", 3}}, log);
    std::vector<double> r;  // residuals of step 30, while above round-off
    for (const ResidualRow& row : log.residuals)
      if (row.lstp == 30 && row.fErr > 1e-12) r.push_back(row.fErr);
    REQUIRE(r.size() >= 4);
    const size_t k = r.size() - 1;
    const double order = std::log(r[k] / r[k - 1]) / std::log(r[k - 1] / r[k - 2]);
    CHECK(order > 1.8);  // quadratic: 2 in exact arithmetic
  }

  TEST_CASE("ample: GIMP compaction error falls at rate >= 0.9 from nelsy 8 to 64") {
    std::vector<double> err;
    for (int nelsy : {8, 64}) {
      RunLog log;
      const std::vector<std::pair<std::string, double>> set = {{"nelsy", nelsy}, {"mpType", 2}};
      const Analysis an = runSetup("compaction", set, log);
      err.push_back(result("compaction", an, set, "error"));
    }
    const double rate = std::log(err[0] / err[1]) / std::log(8.0);
    CHECK(rate >= 0.9);
  }

  TEST_CASE("ample: collapse GIMP 3x3 / h = 1 m matches [AMPLE] table 5 (13.781 / 6.194 m)") {
    RunLog log;
    const std::vector<std::pair<std::string, double>> set = {{"a", 2}, {"mp", 3}};
    const Analysis an = runSetup("collapse", set, log);
    CHECK(std::abs(result("collapse", an, set, "extent") - 13.781) <= 0.01);
    CHECK(std::abs(result("collapse", an, set, "height") - 6.194) <= 0.01);
  }

  TEST_CASE("ample: stretch reaction equals the closed-form plane-strain von Mises stretch (MPM / GIMP / CPDI1 / CPDI2)") {
    // E = 1000, nu = 0, rho_y = 400, L0 = 2, du = 0.2, 20 steps (setups/stretch.cpp defaults)
    const std::vector<double> tx = stretchClosedForm(20, 2.0, 0.2, 1000, 0.0, 400);
    // the reference itself: elastic tau_xx = E ln(lambda_x) up to the yield stretch
    // ln(lambda_y) = rho_y / (E sqrt(2/3)) = 0.4899 (L = 3.264 m, in step 7); beyond it the
    // stress stays on the surface and tends to the plane-strain limit sqrt(2) rho_y
    for (int k = 1; k <= 6; ++k) CHECK(tx[k - 1] == doctest::Approx(1000 * std::log((2 + 0.2 * k) / 2)).epsilon(1e-12));
    CHECK(tx[6] * 2 / 1.7 < tx[5] * 2 / 1.6);  // the reaction falls in step 7 ([CPDI])
    CHECK(tx[19] > 400 * std::sqrt(1.5));
    CHECK(tx[19] < 400 * std::sqrt(2.0));
    for (int t = 1; t <= 4; ++t) {
      CAPTURE(t);
      RunLog log;
      const std::vector<std::pair<std::string, double>> set = {{"mpType", t}};
      const Analysis an = runSetup("stretch", set, log);
      REQUIRE(an.history.size() == 20);
      for (int k = 1; k <= 20; ++k) {
        CAPTURE(k);
        const double lx = (2 + 0.2 * k) / 2, R = tx[k - 1] * 2.0 / lx;  // sigma_xx * height
        CHECK(an.history[k - 1][1].second == doctest::Approx(R).epsilon(1e-8));
      }
      for (const MaterialPoint& mp : an.mpData) {  // uniform: sigma_yy = 0, sigma_xx = tau / J
        CHECK(std::abs(mp.sig(1)) <= 1e-8 * 400);
        CHECK(vonMisesRho(mp.sig * mp.F.determinant()) == doctest::Approx(400).epsilon(1e-8));
      }
    }
  }

  TEST_CASE("ample: simple shear gives the closed-form Hencky stress (MPM / CPDI2 / elastic) and stays on the von Mises surface (VM)") {
    const double E = 10e3, nu = 0.3, rhoY = 5e3, dg = 0.2;  // 10 steps to gamma = 2
    // the reference itself: the larger eigenvalue of b is exp(2 asinh(g / 2))
    const auto e2 = henckySimpleShear(2.0);
    CHECK(std::sqrt(e2[0] * e2[0] + e2[2] * e2[2]) == doctest::Approx(std::asinh(1.0)).epsilon(1e-13));
    CHECK(std::abs(e2[0] + e2[1]) <= 1e-14);  // isochoric: tr eps = ln J = 0
    for (int t : {1, 4})
      for (int c : {1, 2}) {
        CAPTURE(t);
        CAPTURE(c);
        RunLog log;
        const std::vector<std::pair<std::string, double>> set = {
            {"mpType", t}, {"cmType", c}, {"prescribe", 2}, {"lstps", 10}, {"dl", 2}};
        const Analysis an = runSetup("shear", set, log);
        REQUIRE(an.history.size() == 10);
        for (int k = 1; k <= 10; ++k) {  // mean sigma_xy of every step while elastic
          const Vector6d ref = shearStressClosedForm(k * dg, E, nu);
          if (c == 2 && vonMisesRho(ref) >= rhoY) break;
          CAPTURE(k);
          CHECK(an.history[k - 1][2].second == doctest::Approx(ref(3)).epsilon(1e-9));
        }
        const Vector6d ref = shearStressClosedForm(2.0, E, nu);
        for (const MaterialPoint& mp : an.mpData) {
          if (c == 1) {
            CHECK((mp.sig - ref).norm() <= 1e-9 * ref.norm());
          } else {
            REQUIRE(vonMisesRho(ref) > rhoY);                                   // it has yielded
            CHECK(vonMisesRho(mp.sig) == doctest::Approx(rhoY).epsilon(1e-9));  // on the surface
            CHECK(std::abs(mp.sig.head<3>().sum()) <= 1e-9 * rhoY);              // p = 0 (J = 1)
          }
        }
        if (c == 2) CHECK(result("shear", an, set, "error") < 1e-9);  // uniform: path-dependent VM
      }
  }

  TEST_CASE("ample: simple shear on the paper's boundary cells gives the analytic stress at every point (MPM and CPDI2 / elastic and VM)") {
    // [Lagrangian] sec 7.2 as printed: dl = 6 m over 30 steps, h = 0.125 m, 3 x 3 points;
    // only the nodes of the cells holding the outer layer of points are sheared, the
    // interior nodes are solved for. The rows of points stay uniform, so the interior
    // nodes balance the homogeneous stress and every point must carry it. Without the
    // round-off tolerance of elemForMP/SvpMPM the MPM points that land on grid lines
    // (40 of them after step 1) are split unevenly between cells: error 0.81 (elastic),
    // no convergence in step 6 (VM). CPDI2 accumulates round-off (5e-7 / 8e-6 at the
    // end); the paper reports an error of the order of 1e-5.
    const double mu = 10e3 / (2.0 * 1.3);  // E = 10 kPa, nu = 0.3
    for (int t : {1, 4})
      for (int c : {1, 2}) {
        CAPTURE(t);
        CAPTURE(c);
        const double tolerance = (t == 1) ? 1e-10 : 1e-4;
        RunLog log;
        const std::vector<std::pair<std::string, double>> set = {
            {"mpType", t}, {"cmType", c}, {"prescribe", 1}};
        const Analysis an = runSetup("shear", set, log);
        REQUIRE(an.history.size() == 30);                       // every step converged
        CHECK(result("shear", an, set, "error") < tolerance);  // against the one-point reference
        if (c == 1) {
          // closed-form Hencky stress of simple shear by gamma = 6, by hand: b = F F' has
          // the eigenvalues exp(+-2a) with sinh a = gamma/2, so ln(b)/2 = a N with
          // N = [gamma/2 1; 1 -gamma/2] / sqrt(1 + gamma^2/4); J = 1 and tau = 2 mu eps
          const double g = 6.0, a = std::asinh(g / 2.0), n = std::sqrt(1.0 + g * g / 4.0);
          Vector6d ref = Vector6d::Zero();
          ref(0) = 2.0 * mu * a * (g / 2.0) / n;
          ref(1) = -ref(0);
          ref(3) = 2.0 * mu * a / n;  // 4423.41 Pa
          double worst = 0.0;
          for (const MaterialPoint& mp : an.mpData) worst = std::max(worst, (mp.sig - ref).norm() / ref.norm());
          CHECK(worst < tolerance);
        }
      }
  }

  TEST_CASE("ample: prescribed homogeneous stretch through the whole loop gives uniform stress") {
    // the block [1,3]^2 stretches about its centre (2,2); every node but the
    // centre one is prescribed, so the centre node's force balance is tested
    Analysis an = testing::smallBlock(MpType::GIMP, CmType::Elastic, 2);
    an.lstps = 4;
    const Eigen::Matrix2d H = (Eigen::Matrix2d() << 0.02, 0.0, 0.0, 0.01).finished();
    const Vector2d c(2, 2);
    for (int n = 0; n < an.mesh.nodes(); ++n) {
      const Vector2d X = an.mesh.coord.row(n).transpose();
      if ((X - c).norm() < 1e-12) continue;
      const Vector2d du = H * (X - c);  // increment per load step
      for (int i = 0; i < nD; ++i) an.mesh.bc.push_back({dof(n, i), du(i)});
    }
    RunLog log;
    solveRun(an, log);
    // by hand: F = diag(1.02^4, 1.01^4, 1) (the grid resets each step), Hencky strain
    // diag(4 ln 1.02, 4 ln 1.01, 0), tau = lambda tr(eps) I + 2 mu eps (E = 1e6, nu = 0.3),
    // sigma = tau / (1.02^4 1.01^4)
    const double ex = 4 * std::log(1.02), ey = 4 * std::log(1.01), J = std::pow(1.02 * 1.01, 4);
    const double lam = lameLambda(1e6, 0.3), mu = lameMu(1e6, 0.3);
    Vector6d sigA;
    sigA << lam * (ex + ey) + 2 * mu * ex, lam * (ex + ey) + 2 * mu * ey, lam * (ex + ey), 0, 0, 0;
    sigA /= J;
    for (const MaterialPoint& mp : an.mpData) CHECK((mp.sig - sigA).norm() <= 1e-8 * sigA.norm());
  }
}

// [Lagrangian] table 8 prints the residuals of load step 10 of this collapse, pass 0 included:
// 2.656e+00, 2.697e-04, 1.626e-09. Pass 0 is normalised by |fext| (frct is still 0), as in
// the paper; only a step without loads (fext = 0) takes the last reactions instead
TEST_SUITE("ample") {
  TEST_CASE("ample: collapse 6x6 at h = 1 m reproduces the load step 10 residuals of [Lagrangian] table 8") {
    const Setup* s = findSetup("collapse");
    Params P = s->params();
    setParam(P, "mp", 6);
    Analysis an = s->setupGrid(P);
    RunLog log;
    solveRun(an, log, RunOptions{"", 0, true, 10});
    std::vector<double> r;
    for (const ResidualRow& row : log.residuals)
      if (row.lstp == 10) r.push_back(row.fErr);
    REQUIRE(r.size() >= 3);                                  // a 4th pass takes it below tol
    CHECK(r[0] == doctest::Approx(2.656e+00).epsilon(5e-4).scale(0));  // printed to 4 digits
    CHECK(r[1] == doctest::Approx(2.697e-04).epsilon(5e-4).scale(0));
    CHECK(r[2] == doctest::Approx(1.626e-09).epsilon(5e-4).scale(0));
  }
}

// eq 35 in the passes after the first solve: |oobf| / |fext + frct|, frct the reactions of
// this pass (only pass 0 of a step without loads takes the last step's reactions). The
// stretch setup (E = 1000, nu = 0, L0 = H = 2 m, du = 0.2 m a step) is elastic up to step 6
// and homogeneous: with nu = 0 the Hencky stress of x = diag(lam, 1) X is tau_xx = E ln lam,
// tau_yy = 0 (free top, no vertical stretch), sigma_xx = E ln(lam) / lam, and every nodal force
// vector of the pulled and the fixed side is the same pattern times the resultant
// R(lam) = H E ln(lam) / lam. Pass 1 of step k applies the whole uniform increment (the
// homogeneous field solves the linearised free rows), from lam_a = 1 + 0.1 (k - 1) to
// lam_b = lam_a + 0.1, so by hand
//   frct = R(lam_a) + R'(lam_a) 0.1 (last state + tangent times increment),
//   oobf = frct - R(lam_b) (on the same pattern; the free rows balance),
//   fErr = |R(lam_a) + 0.1 R'(lam_a) - R(lam_b)| / |R(lam_a) + 0.1 R'(lam_a)|,
// R'(lam) = H E (1 - ln lam) / lam^2. Step 2: 0.058723; with the last step's reactions
// R(lam_a) as denominator it would be 0.109402. Pass 0 of steps k >= 2 (no load, nothing
// applied yet) is R(lam_a) / R(lam_a) = 1. Tolerance 1e-9 relative (the steps converge to 1e-14)
TEST_SUITE("ample") {
  TEST_CASE("ample: stretch's pass-1 residuals (eq 35) are the hand values normalised by this pass's reactions") {
    const double E = 1000, H = 2, dlam = 0.1;
    const auto R = [&](double lam) { return H * E * std::log(lam) / lam; };
    const auto dR = [&](double lam) { return H * E * (1 - std::log(lam)) / (lam * lam); };
    // the hand value itself, step 2: ln 1.1 = 0.0953102, ln 1.2 = 0.1823216
    CHECK(std::abs(R(1.1) + dlam * dR(1.1) - R(1.2)) / (R(1.1) + dlam * dR(1.1)) ==
          doctest::Approx(0.058723).epsilon(1e-5));
    for (int t = 1; t <= 4; ++t) {
      CAPTURE(t);
      RunLog log;
      runSetup("stretch", {{"mpType", t}, {"lstps", 6}}, log);
      for (int k = 1; k <= 6; ++k) {
        CAPTURE(k);
        const double la = 1 + dlam * (k - 1), lb = la + dlam;
        const double frct = R(la) + dlam * dR(la), hand = std::abs(frct - R(lb)) / frct;
        int seen = 0;
        for (const ResidualRow& row : log.residuals) {
          if (row.lstp != k) continue;
          if (row.NRit == 1) {
            CHECK(row.fErr == doctest::Approx(hand).epsilon(1e-9));
            ++seen;
          }
          if (row.NRit == 0 && k >= 2) {
            CHECK(row.fErr == doctest::Approx(1.0).epsilon(1e-9));
            ++seen;
          }
        }
        CHECK(seen == (k >= 2 ? 2 : 1));
      }
    }
  }
}

TEST_SUITE("ample") {
  // solve() with the default hooks is fig 4 alone: the core functions, no remedy, no log.
  // The program's hooks must add nothing to a plain run's numbers.
  // (the default lone=2 keeps the paper's free set while every step converges; the collapse
  // has lone nodes from load step 34 on, which lone=1 would leave out)
  // (with the core's point loops: the fast ones of an optimised build agree with them to
  // round-off only, tests/test_pointLoops.cpp; over these whole runs measured within 1e-12)
  TEST_CASE("solve: the core alone (default hooks) gives the program's hooks' points bit for bit (compaction, collapse)") {
    for (const std::string name : {"compaction", "collapse"}) {
      CAPTURE(name);
      const Setup* s = findSetup(name);
      Params P = s->params();
      Analysis plain = s->setupGrid(P), full = s->setupGrid(P), fast = s->setupGrid(P);
      solve(plain);                                                  // Hooks(): the core's
      RunLog log, fastLog;
      RunOptions coreLoops{"", 0, true, 0};
      coreLoops.basisLoop = nullptr, coreLoops.pointLoop = detMPs;   // nullptr: the serial elemMPinfo
      solveRun(full, log, coreLoops);
      solveRun(fast, fastLog);                                       // detMPsFast in an optimised build
      REQUIRE(plain.mpData.size() == full.mpData.size());
      double sigDiff = 0.0, sigMax = 0.0;
      for (size_t p = 0; p < full.mpData.size(); ++p) {
        CAPTURE(p);
        CHECK(plain.mpData[p].mpC == full.mpData[p].mpC);
        CHECK(plain.mpData[p].sig == full.mpData[p].sig);
        CHECK(plain.mpData[p].F == full.mpData[p].F);
        sigDiff = std::max(sigDiff, (fast.mpData[p].sig - plain.mpData[p].sig).cwiseAbs().maxCoeff());
        sigMax = std::max(sigMax, plain.mpData[p].sig.cwiseAbs().maxCoeff());
      }
      CHECK(plain.frct == full.frct);
      CHECK(log.converged);
      CHECK(fastLog.converged);
      CHECK(sigDiff <= 1e-11 * sigMax);
    }
  }

  TEST_CASE("solve: a load step that does not converge throws NewtonFailure naming the step and fErr (core, no hooks)") {
    const Setup* s = findSetup("collapse");
    Params P = s->params();
    setParam(P, "NRitMax", 3);                                     // too few passes for the plastic steps
    Analysis an = s->setupGrid(P);
    std::string what;
    try {
      solve(an);
    } catch (const NewtonFailure& e) {
      what = e.what();
      CHECK(e.kind == Failure::NotConverged);
    }
    CHECK(what.find("did not converge: fErr = ") != std::string::npos);
    CHECK(what.find("after 3 Newton-Raphson passes") != std::string::npos);
    CHECK(what.rfind("load step ", 0) == 0);
  }

  TEST_CASE("solve: each hook is called in its phase, in fig 4's order, once per pass or step") {
    const Setup* s = findSetup("compaction");
    Analysis an = s->setupGrid(s->params());
    struct Recorder : Hooks {                                        // each hook marks its call
      std::string& calls;
      long& passes;
      Recorder(std::string& c, long& p) : calls(c), passes(p) {}
      void startStep(Analysis&, const Increment& inc) const override { calls += "S" + std::to_string(inc.lstp); }
      void stepTerms(Analysis&, const Increment&, Eigen::VectorXd&) const override { calls += "t"; }
      void passTerms(const Eigen::VectorXd&, DetMPsOut&, Eigen::VectorXd&) const override { calls += "p"; }
      void afterPass(const Analysis&, const Increment&, int NRit, double) const override {
        calls += std::to_string(NRit), passes++;
      }
      void afterUpdate(Analysis&, const Increment&, int, double) const override { calls += "u"; }
      void endStep(Analysis&, const Increment&) const override { calls += "E"; }
    };
    std::string calls;
    long passes = 0;
    const Recorder h(calls, passes);
    solve(an, h);
    // S1 t (p pass)... u E S2 t (p pass)... u E: passes 0, 1, ... of each step in turn
    CHECK(calls.substr(0, 7) == "S1tp0p1");
    CHECK(calls.find("uES2t") != std::string::npos);
    CHECK(calls.back() == 'E');
    CHECK(std::count(calls.begin(), calls.end(), 'S') == an.lstps);
    CHECK(std::count(calls.begin(), calls.end(), 't') == an.lstps);
    CHECK(std::count(calls.begin(), calls.end(), 'u') == an.lstps);
    CHECK(std::count(calls.begin(), calls.end(), 'E') == an.lstps);
    CHECK(std::count(calls.begin(), calls.end(), 'p') == passes);   // passTerms once a pass
    CHECK(passes >= 2 * an.lstps);                                  // NRit < 2: two passes at least
  }
}

TEST_SUITE("ample") {
  TEST_CASE("solve: the core alone refuses an analysis that needs the program's hooks (a setup's beforeStep: the stretch) with an InputError naming solveRun") {
    const Setup* s = findSetup("stretch");
    Analysis an = s->setupGrid(s->params());
    an.name = "stretch";
    REQUIRE(an.beforeStep);                                          // the stretch sets its bcs there
    CHECK_THROWS_WITH_AS(solve(an), doctest::Contains("run it with solveRun"), InputError);
    RunLog log;
    Analysis again = s->setupGrid(s->params());
    CHECK_NOTHROW(solveRun(again, log));
    CHECK(log.converged);
  }
}
