//--------------------------------------------------------------------------
// funnel — an elastic body forced through a curved funnel ([Boundaries] sec 5.6)
//--------------------------------------------------------------------------
// The funnel's walls are curved implicit rollers (ample/boundaries/ibStiffness.h), one
// straight segment per grid column (the paper: one per cell the curve crosses;
// where the wall is steep a segment crosses two cells), and the body's right
// edge is pushed to the left by a PrescribedNormal implicit boundary, 4 mm per
// load step over six steps (sec 5.6). The text gives 4 mm per step as "three
// times the grid spacing", and also a "4 mm by 4 mm grid": we take the first,
// h = 4/3 mm. The outline is not in the text; ours (mm, symmetric about y = 0):
// half height H(x) = 15 for x >= 50, 8 + 3.5 (1 - cos(pi (x - 20) / 30)) for
// 20 <= x <= 50 (the curved part, from 15 down to 8), 8 for x <= 20 (the
// outlet); walls from x = -20 to 86. The body fills the funnel from x = 40
// to 84 (its left end already in the curved part); the right edge stays in
// the straight part throughout. K2 and K3 of the walls take the curve's normal,
// varying along each segment (sec 4; normals=segments: each segment's own, which
// locks the walls: a continuous field tangent to two segments vanishes at their kink). 2 x 2 standard MPM points per cell, cut by the
// walls (sec 4), E = 1000 MPa, nu = 0.3, delta = 1e-6 h, small strain (SS,
// the paper) or formulation=UL (finite deformation).
// afterStep counts the points outside the walls (signed distance to the
// polyline below -1e-9 h) and the largest such distance.
// Outputs: history.csv: lstp, push (m), outside (points), worst (m), load (kN/m);
//          results: the same at the last step
// Tests:   tests/test_ibMoving.cpp
//--------------------------------------------------------------------------
#include "formCoord2D.h"
#include "setupHelpers.h"
#include <cmath>

namespace ample::funnel {

static const double mm = 1e-3;
static double halfHeight(double x) {  // x in m; H in m
  const double X = x / mm;
  if (X >= 50) return 15 * mm;
  if (X <= 20) return 8 * mm;
  return (8 + 3.5 * (1 - std::cos(M_PI * (X - 20) / 30))) * mm;
}

static double slope(double x) {  // dH/dx
  const double X = x / mm;
  return X <= 20 || X >= 50 ? 0.0 : 3.5 * M_PI / 30 * std::sin(M_PI * (X - 20) / 30);
}

// the parameters and their defaults (their ranges and help: params)
struct Funnel : IbCommon {
  double h = 4.0 / 3 * mm;
  int normals = 1;                                  // 0 segments, 1 curve
  double step = 4 * mm;
  Funnel() {
    lstps = 6;
    mp = 2;
  }
};

Params params(Funnel& p) {
  Params P = ibCommonParams(p);
  param(P, "h", p.h).range(0.25 * mm, 4 * mm).help("grid spacing (m)");
  param(P, "normals", p.normals).choice(0, {"segments", "curve"})
      .help("normal of K2, K3 on the walls: each segment's own, or the curve's, varying along "
            "the segment (sec 4)");
  param(P, "step", p.step).range(0, 10 * mm).help("push of the right edge per load step (m)");
  return P;
}

Analysis setupGrid(const Funnel& p) {
  const double h = p.h, delta = p.delta;
  const Vector2d o(24 * mm, 16 * mm);                             // funnel axes: x - 24, y - 16 mm
  const int nx = int(std::ceil(114 * mm / h)), ny = int(std::ceil(32 * mm / h));
  Analysis an = baseAnalysis(p);
  an.mesh = formCoord2D(nx, ny, nx * h, ny * h);
  auto wall = [&](double x, double side) { return Vector2d(o + Vector2d(x, side * halfHeight(x))); };
  std::vector<Vector2d> top, bottom, nTop, nBottom;               // walls: a point per grid line
  for (int i = 0; i <= nx; ++i) {
    const double x = i * h - o(0);
    if (x < -20 * mm - 1e-12 || x > 86 * mm + h) continue;
    bottom.push_back(wall(x, -1));
    nBottom.push_back(Vector2d(slope(x), 1).normalized());        // inward: up
    top.insert(top.begin(), wall(x, 1));                          // right to left: solid below
    nTop.insert(nTop.begin(), Vector2d(slope(x), -1).normalized());
  }
  const double xr = 84 * mm;
  const bool curve = p.normals == 1;
  addBoundary(an, bottom, BoundaryType::Roller, delta).curveNormal = curve ? nBottom : Polygon{};
  addBoundary(an, {wall(xr, -1), wall(xr, 1)}, BoundaryType::PrescribedNormal, delta)
      .du = {Vector2d(-p.step, 0)};
  addBoundary(an, top, BoundaryType::Roller, delta).curveNormal = curve ? nTop : Polygon{};
  ibSettings(an, p);
  Polygon body{wall(40 * mm, -1)};                                // the body: x in [40, 84] mm
  for (const Vector2d& x : bottom)
    if (x(0) - o(0) > 40 * mm && x(0) - o(0) < xr) body.push_back(x);
  body.push_back(wall(xr, -1)), body.push_back(wall(xr, 1));
  for (const Vector2d& x : top)
    if (x(0) - o(0) > 40 * mm && x(0) - o(0) < xr) body.push_back(x);
  body.push_back(wall(40 * mm, 1));
  fillPolygon(an.mpData, Vector2d::Zero(), nx, ny, an.mesh.h, p, 0.0, body);
  an.afterStep = [step = p.step, h](Analysis& a, int lstp, double /*lf: push = step x lstp*/) {
    int outside = 0;
    double worst = 0;                                             // most negative signed distance
    for (const MaterialPoint& mp : a.mpData)
      for (int w : {0, 2})                                        // the walls
        for (int s = 0; s < boundariesOf(a)[w].segments(); ++s) {
          const Boundary& b = boundariesOf(a)[w];
          const double xa = std::min(b.x[s](0), b.x[s + 1](0)), xb = std::max(b.x[s](0), b.x[s + 1](0));
          if (mp.mpC(0) < xa || mp.mpC(0) > xb) continue;
          const double phi = signedDistance(b, s, mp.mpC);
          worst = std::min(worst, phi);
          if (phi < -1e-9 * h) ++outside;
        }
    a.history.push_back({{"lstp", lstp}, {"push", step * lstp}, {"outside", double(outside)},
                         {"worst", worst}, {"load_kN", a.ibForce[1].dot(Vector2d(-1, 0)) / 1e3}});
  };
  return an;
}

Results results(const Analysis& an, const Funnel&) {
  if (an.history.empty()) return {};
  double outside = 0, worst = 0;
  for (const auto& row : an.history) outside += row[2].second, worst = std::min(worst, row[3].second);
  return {{"push", an.history.back()[1].second}, {"outside", outside}, {"worst_m", worst},
          {"load_kN", an.history.back()[4].second}, {"points", double(an.mpData.size())}};
}

// this setup's line in the table of setups/setups.cpp
SetupCalls calls() { return {params, setupGrid, results}; }

}  // namespace ample::funnel
