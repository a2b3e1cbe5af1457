//--------------------------------------------------------------------------
// ibblock — compression of a contained block by implicit boundaries ([Boundaries] sec 5.1)
//--------------------------------------------------------------------------
// A 100 x 100 mm block (L = 0.1 m) in rollers on three sides (implicit
// boundaries, ample/boundaries/ibStiffness.h), its fourth side pushed 1 mm (du = 1e-3 m)
// along its inward normal in one load step (PrescribedNormal: zero shear). The
// block is rotated by theta (degrees) about its centre, which sits on a node of
// a grid aligned with x, y (h = 10 mm, a 2N x 2N grid with room for every
// theta), so that at theta = 0 and 90 its sides lie on grid lines. Points:
// fillPolygon (sec 4), mp x mp per cell (the paper: one), standard MPM (the
// paper's MPM of sec 2), small strain (formulation SS, sec 2), E = 1000 MPa,
// nu = 0.3, delta = 1e-6 h (sec 5.1). In the block's axes (x' along the push,
// from the fixed side) the exact solution is u' = (-eps x', 0), eps = du / L,
// plane-strain sigma' = -eps E / ((1 + nu)(1 - 2 nu)) {1 - nu, nu, 0}
// = {-13.46, -5.77, 0} MPa (compression; the paper quotes magnitudes).
// multiples of 90 degrees use exact cos, sin, so 0 and 90 are the same problem.
// Outputs: results: ru (eq 29), r_sxx, r_syy (eq 30; sigma_x'x', sigma_y'y'),
//          sxx_mean (MPa), points
// Tests:   tests/test_ibStiffness.cpp
//--------------------------------------------------------------------------
#include "formCoord2D.h"
#include "setupHelpers.h"
#include <cmath>

namespace ample::ibblock {

static const double L = 0.1;  // block side (m)

// the parameters and their defaults (their ranges and help: params)
struct Ibblock : IbCommon {
  double theta = 0, h = 0.01, du = 1e-3;
  Ibblock() {
    lstps = 1;
    mp = 1;
  }
};

Params params(Ibblock& p) {
  Params P = ibCommonParams(p);
  // results() compares with the one-push solution: a second step pushes again
  P.named("lstps").integer(1, 1).help("load steps: one (the exact solution is that of one push du)");
  param(P, "theta", p.theta).range(-360, 360).help("rotation of the block to the grid (degrees)");
  param(P, "h", p.h).range(1e-4, 0.05).help("grid spacing (m); L / h should be a whole number");
  param(P, "du", p.du).range(0, 0.05).help("push of the fourth side (m), in one load step");
  return P;
}

Analysis setupGrid(const Ibblock& p) {
  const double h = p.h, delta = p.delta;
  const int N = int(std::ceil((L / std::sqrt(2.0) + h) / h - 1e-9));  // half the grid, in cells
  Analysis an = baseAnalysis(p);
  an.mesh = formCoord2D(2 * N, 2 * N, 2 * N * h, 2 * N * h);
  const Eigen::Matrix2d R = rotationDegrees(p.theta);
  const Vector2d c(N * h, N * h);                                   // centre of the block
  auto corner = [&](double x, double y) { return Vector2d(c + R * Vector2d(x - L / 2, y - L / 2)); };
  const Vector2d a = corner(0, 0), b = corner(L, 0), d = corner(L, L), e = corner(0, L);
  addBoundary(an, {a, b}, BoundaryType::Roller, delta);             // bottom
  addBoundary(an, {b, d}, BoundaryType::PrescribedNormal, delta).du = {R * Vector2d(-p.du, 0)};
  addBoundary(an, {d, e}, BoundaryType::Roller, delta);             // top
  addBoundary(an, {e, a}, BoundaryType::Roller, delta);             // left (fixed side)
  ibSettings(an, p);
  fillPolygon(an.mpData, Vector2d::Zero(), 2 * N, 2 * N, an.mesh.h, p, 0.0, solidPolygon(boundariesOf(an)));
  return an;
}

Results results(const Analysis& an, const Ibblock& p) {
  const double E = p.E, nu = p.nu, eps = p.du / L;
  const Eigen::Matrix2d R = rotationDegrees(p.theta);
  const double N = std::ceil((L / std::sqrt(2.0) + p.h) / p.h - 1e-9);
  const Vector2d a = Vector2d(N, N) * p.h - R * Vector2d(L / 2, L / 2);  // fixed corner
  const double k = -eps * E / ((1 + nu) * (1 - 2 * nu));
  const double sxx = k * (1 - nu), syy = k * nu;                    // exact, block axes
  double V = 0, ru = 0, rx = 0, ry = 0, mean = 0;
  for (const MaterialPoint& mp : an.mpData) {
    const Vector2d X = R.transpose() * (mp.X0 - a);                 // block axes
    const Vector2d ue = R * Vector2d(-eps * X(0), 0.0);
    Eigen::Matrix2d s;
    s << mp.sig(0), mp.sig(3), mp.sig(3), mp.sig(1);
    const Eigen::Matrix2d sl = R.transpose() * s * R;               // stress in block axes
    V += mp.vp;
    ru += mp.vp * (mp.u - ue).norm() / ue.norm();                   // eq 29
    rx += mp.vp * std::abs(sl(0, 0) - sxx) / std::abs(sxx);         // eq 30
    ry += mp.vp * std::abs(sl(1, 1) - syy) / std::abs(syy);
    mean += mp.vp * sl(0, 0);
  }
  Results r{{"ru", ru / V}, {"r_sxx", rx / V}, {"r_syy", ry / V}, {"sxx_mean_MPa", mean / V / 1e6},
            {"points", double(an.mpData.size())}};
  if (syy == 0) {                                                   // nu = 0 or du = 0
    r[2].second = NAN;
    r.undefined("r_syy", "the exact sigma_y'y' is 0 (nu = 0 or du = 0): a relative error is undefined");
  }
  if (eps == 0) {
    r[0].second = r[1].second = NAN;
    r.undefined("ru", "no load (du = 0): the error is relative to the exact displacement 0");
    r.undefined("r_sxx", "no load (du = 0): the error is relative to the exact sigma_x'x' = 0");
  }
  return r;
}

// this setup's line in the table of setups/setups.cpp
SetupCalls calls() { return {params, setupGrid, results}; }

}  // namespace ample::ibblock
