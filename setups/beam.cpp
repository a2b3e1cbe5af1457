//--------------------------------------------------------------------------
// beam — large-deflection elastic cantilever with a tip load ([AMPLE] sec 5.2)
//--------------------------------------------------------------------------
// Beam l = 10 m by d = 1 m along the top of an 11 m x 10 m grid, h = 0.5 m / a
// (a = 2: h = 0.25 m as in [AMPLE] figs 12 and 14),
// mp x mp GIMP points per cell (6 x 6), E = 12 MPa, nu = 0.2, no gravity.
// Tip load P = 100 kN downwards, split between the two points nearest the
// free end either side of the neutral axis, over 50 load steps. Rollers on
// x = 0 (x fixed), the root pinned at mid-depth (x and y fixed at (0, 9.5)).
//   ample beam a=2 mp=3
// Outputs: Analysis · results: tip displacement (mean of the two loaded points);
//          history.csv: load factor and tip displacement over l at every step
// Tests:   tests/test_ample.cpp (setups run), tests/test_detMPs.cpp
//--------------------------------------------------------------------------
#include "formCoord2D.h"
#include "setupHelpers.h"
#include <cmath>

namespace ample::beam {

constexpr double lx = 11, ly = 10, l = 10, d = 1;  // grid and beam sizes (m)

// the parameters and their defaults (their ranges and help: params)
struct Beam : Common {
  int a = 2;
  double P = 100e3;
  Beam() {
    lstps = 50;
    mp = 6;
    E = 12e6;
    nu = 0.2;
  }
};

Params params(Beam& p) {
  Params P = commonParams(p);
  param(P, "a", p.a).integer(1, 64).help("grid refinement: h = 0.5 m / a");
  param(P, "P", p.P).atLeast(0).help("tip load, acting downwards (N)");
  return P;
}

Analysis setupGrid(const Beam& p) {
  const int a = p.a;
  Analysis an = baseAnalysis(p);
  an.mesh = formCoord2D(22 * a, 20 * a, lx, ly);
  const Vector2d h = an.mesh.h;
  const double eps = 1e-9 * h(0), yNA = ly - d / 2;  // neutral axis
  fixDofs(an.mesh, 0, [&](double X, double) { return X < eps; });
  fixDofs(an.mesh, 1, [&](double X, double Y) { return X < eps && std::abs(Y - yNA) < eps; });
  fillBlock(an.mpData, Vector2d(0, ly - d), 20 * a, 2 * a, h, p, 0.0);

  double xMax = -INFINITY;  // the loaded points: largest x, nearest the axis above and below
  for (const MaterialPoint& mp : an.mpData) xMax = std::max(xMax, mp.mpC(0));
  int above = -1, below = -1;
  for (int p = 0; p < int(an.mpData.size()); ++p) {
    const Vector2d& x = an.mpData[p].mpC;
    if (x(0) < xMax - eps) continue;
    if (x(1) > yNA && (above < 0 || x(1) < an.mpData[above].mpC(1))) above = p;
    if (x(1) < yNA && (below < 0 || x(1) > an.mpData[below].mpC(1))) below = p;
  }
  an.mpData[above].fp = an.mpData[below].fp = Vector2d(0, -p.P / 2);
  an.afterStep = [above, below](Analysis& a, int lstp, double lf) {  // tip history
    const Vector2d u = 0.5 * (a.mpData[above].u + a.mpData[below].u);
    a.history.push_back({{"lstp", lstp}, {"load_factor", lf},
                         {"tip_u_over_l", u(0) / l}, {"tip_v_over_l", u(1) / l}});
  };
  return an;
}

Results results(const Analysis& an, const Beam&) {
  Vector2d u = Vector2d::Zero();
  for (const MaterialPoint& mp : an.mpData)
    if (mp.fp.squaredNorm() > 0) u += 0.5 * mp.u;
  return {{"tip_u", u(0)}, {"tip_v", u(1)}, {"tip_u_over_l", u(0) / l}, {"tip_v_over_l", u(1) / l}};
}

// this setup's line in the table of setups/setups.cpp
SetupCalls calls() { return {params, setupGrid, results}; }

}  // namespace ample::beam
