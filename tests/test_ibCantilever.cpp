// Tests of the setup ibcantilever ([Boundaries] sec 5.4): a 100 x 20 mm plane-strain cantilever
// fixed at one end by an implicit boundary, under a body force across the beam, at a small
// size (h = 4 mm, 5 x 5 points per cell: ~0.1 s a run). Checks:
//  - 0 and 90 degrees are the same discretisation (the model turned about a grid node, the
//    grid mapped onto itself): every point's displacement in beam axes agrees to 1e-9 of the
//    tip deflection;
//  - one load step (points at their original places) against the plane-strain Timoshenko
//    cantilever under q = b d: v(s) = q s^2 (6 L^2 - 4 L s + s^2) / (24 E' I)
//    + q (L s - s^2 / 2) / (kappa G d), E' = E / (1 - nu^2), I = d^3 / 12, kappa = 5/6,
//    s from the support (e.g. Timoshenko & Gere, Mechanics of Materials, cantilever under
//    uniform load, plus the shear deflection), written here from the points' data;
//  - the reaction of the implicit boundary (sum of an.frct) equals the total body force
//    (sum of b V over the points) at every load step to 1e-8, at 0 and 45 degrees.
#include "setups/program/run.h"
#include "testProblems.h"
#include <cmath>

using namespace ample;

namespace {
const double L = 0.1, d = 0.02, E = 1e9, nu = 0.3, b = 2e8;

// R^T of the setup's rotation by theta degrees (exact at multiples of 90)
Eigen::Matrix2d toBeam(double theta) {
  double c = std::cos(theta * M_PI / 180), s = std::sin(theta * M_PI / 180);
  if (std::fmod(theta, 90.0) == 0.0) c = std::round(c), s = std::round(s);
  Eigen::Matrix2d Rt;
  Rt << c, s, -s, c;
  return Rt;
}

// h = 4 mm, 5 x 5 points, 3 load steps run through at 0, 45 and 90 degrees; some other small
// sizes meet the cell-crossing mechanism (a point alone in a cell: docs/implicitBoundaries.md)
Analysis cantilever(double theta, int lstps, RunLog& log, double h = 0.004, int mp = 5) {
  return testing::runSetup("ibcantilever", {{"theta", theta}, {"lstps", lstps}, {"h", h}, {"mp", mp}}, log);
}

// the free end x' = 0 in beam axes: the point of least x' (its lower corner is the origin)
Vector2d origin(const Analysis& an, const Eigen::Matrix2d& Rt) {
  Vector2d o = Vector2d::Constant(INFINITY);
  for (const MaterialPoint& mp : an.mpData) o = o.cwiseMin(Rt * mp.X0);
  return o;  // the smallest point coordinates: h / (2 mp) inside the corner
}
}  // namespace

TEST_SUITE("ibCantilever") {
  TEST_CASE("ibcantilever: 0 and 90 degrees are the same discretisation") {
    RunLog l0, l90;
    const Analysis a = cantilever(0, 3, l0), c = cantilever(90, 3, l90);
    REQUIRE(l0.converged);
    REQUIRE(l90.converged);
    REQUIRE(a.mpData.size() == c.mpData.size());
    const Eigen::Matrix2d R0 = toBeam(0), R90 = toBeam(90);
    const Vector2d o0 = origin(a, R0), o90 = origin(c, R90);
    double tip = 0, err = 0, posErr = 0;
    for (const MaterialPoint& p : a.mpData) {  // the 90 degree point at the same beam position
      const Vector2d X = R0 * p.X0 - o0;
      const MaterialPoint* q = nullptr;
      for (const MaterialPoint& r : c.mpData)
        if ((R90 * r.X0 - o90 - X).norm() < 1e-9) q = &r;
      REQUIRE(q != nullptr);
      posErr = std::max(posErr, (R90 * q->X0 - o90 - X).norm());
      tip = std::max(tip, p.u.norm());
      err = std::max(err, (R0 * p.u - R90 * q->u).norm());
    }
    CHECK(tip > 0.05);                // the largest point displacement: 71 mm
    CHECK(err / tip < 1e-9);          // measured 9e-13 (round-off: K3 ~ 1e6 K1)
    CHECK(posErr < 1e-12);
  }

  TEST_CASE("ibcantilever: one load step against the plane-strain Timoshenko cantilever") {
    // measured v / v_Timoshenko (mean over the points within 2 mm of the free end):
    // h = 4 mm, 4 x 4: 0.9677; h = 2 mm, 4 x 4: 0.9844 (bilinear cells are stiff in bending
    // and the fully fixed section adds a little; 10 x 10 points, h = 0.5 mm: 0.9906):
    // tolerance 4.5 % and 2.5 % from below, 0.5 % above
    const double q = b * d, Ep = E / (1 - nu * nu), I = d * d * d / 12, G = E / (2 * (1 + nu));
    auto w = [&](double x) {
      const double s = L - x;
      return q * s * s * (6 * L * L - 4 * L * s + s * s) / (24 * Ep * I) + q * (L * s - s * s / 2) / (5.0 / 6 * G * d);
    };
    CHECK(w(0) == doctest::Approx(0.06825 + 0.00312).epsilon(1e-12));  // q L^4 / (8 E' I) + shear
    for (const auto& [h, lo] : {std::pair{0.004, 0.955}, std::pair{0.002, 0.975}}) {
      RunLog log;
      const Analysis an = cantilever(0, 1, log, h, 4);
      REQUIRE(log.converged);
      const Eigen::Matrix2d Rt = toBeam(0);
      const Vector2d o = origin(an, Rt) - Vector2d::Constant(h / 8);  // the corner (h / (2 mp), mp = 4)
      double V = 0, v = 0, vb = 0;
      for (const MaterialPoint& mp : an.mpData) {
        const Vector2d X = Rt * mp.X0 - o;
        if (X(0) >= 0.002) continue;
        V += mp.vp0, v += mp.vp0 * (Rt * mp.u)(1), vb += mp.vp0 * w(X(0));
      }
      const double ratio = -v / vb;
      INFO("h = " << h << ": v / v_Timoshenko = " << ratio);
      CHECK(ratio > lo);
      CHECK(ratio < 1.005);
    }
  }

  TEST_CASE("ibcantilever: the fixed end's reaction is the total body force at every step") {
    for (double theta : {0.0, 45.0}) {
      RunLog log;
      const Analysis an = cantilever(theta, 3, log);
      REQUIRE(log.converged);
      double V = 0;
      for (const MaterialPoint& mp : an.mpData) V += mp.vp0;
      CHECK(V == doctest::Approx(L * d).epsilon(1e-12).scale(0));   // fillPolygon keeps the area
      const Eigen::Matrix2d Rt = toBeam(theta);
      REQUIRE(an.history.size() == 3);
      for (int s = 0; s < 3; ++s) {
        Vector2d F = Vector2d::Zero(), Rct = Vector2d::Zero();  // body force, reaction (beam axes)
        for (const MaterialPoint& mp : an.mpData) F += (s + 1) / 3.0 * Rt * mp.fp;
        CHECK(F(1) == doctest::Approx(-(s + 1) / 3.0 * b * L * d).epsilon(1e-12));  // along -y'
        CHECK(std::abs(F(0)) < 1e-12 * b * L * d);
        for (const auto& kv : an.history[s]) {
          if (kv.first == "R_x") Rct(0) = kv.second;
          if (kv.first == "R_y") Rct(1) = kv.second;
        }
        INFO("theta " << theta << " step " << s + 1 << ": reaction " << Rct.transpose());
        CHECK((Rct + F).norm() / F.norm() < 1e-8);  // measured < 2e-11
      }
      // and the last step's reaction straight from an.frct
      Vector2d Rct = Vector2d::Zero();
      for (int n = 0; n < an.mesh.nodes(); ++n) Rct += Rt * Vector2d(an.frct(dof(n, 0)), an.frct(dof(n, 1)));
      CHECK(std::abs(Rct(1) - b * L * d) / (b * L * d) < 1e-8);
    }
  }
}
