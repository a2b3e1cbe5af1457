//--------------------------------------------------------------------------
// footing — a rough rigid footing pushed into an elastic domain ([Boundaries] sec 5.5)
//--------------------------------------------------------------------------
// A 3 x 3 m elastic domain (E = 1000 MPa, nu = 0.3, plane strain), h = 0.2 m,
// 2 x 2 standard MPM points per cell (sec 5.5), every support an implicit
// boundary (ample/boundaries/ibStiffness.h) with delta = 1e-6 h: the base Fixed, the two
// sides Roller, and the footing a Prescribed segment (rough: both directions)
// of width B on the top surface, centred, pushed down `push` = 1 m over 20
// load steps; it moves with the prescribed displacement, so from the first
// step on it cuts the cells between grid lines (the point of the example).
// The rest of the top is free. The text does not give the footing's width:
// B = 1 m (a third of the domain) is ours. The domain sits one cell in from
// the grid's edges and the grid reaches 3 cells above it (the heave beside
// the footing). Small strain (formulation SS, as the paper) by default; the
// finite-deformation UL formulation with formulation=UL.
// No gravity: the footing's load is the force of the footing boundary on the body.
// Outputs: history.csv: lstp, settlement (m), load (kN per m); results: the
//          final load (kN/m) and the largest |sum of the boundary forces| (N/m)
// Tests:   tests/test_ibStiffness.cpp
//--------------------------------------------------------------------------
#include "ample/errors.h"
#include "formCoord2D.h"
#include "setupHelpers.h"
#include <cmath>

namespace ample::footing {

static const double L = 3.0;  // side of the domain (m)

// the parameters and their defaults (their ranges and help: params)
struct Footing : IbCommon {
  double h = 0.2, B = 1.0, push = 1.0;
  Footing() {
    lstps = 20;
    mp = 2;
  }
};

Params params(Footing& p) {
  Params P = ibCommonParams(p);
  param(P, "h", p.h).range(0.02, 1.0).help("grid spacing (m); 3 / h a whole number");
  param(P, "B", p.B).range(0.1, 3.0).help("footing width (m), centred on the top (ours)");
  param(P, "push", p.push).range(0, 1.5).help("total footing displacement (m), downwards");
  return P;
}

Analysis setupGrid(const Footing& p) {
  const double h = p.h, B = p.B, push = p.push;
  const int n = int(std::lround(L / h));
  if (std::abs(n * h - L) > 1e-9 * L)
    throw InputError("footing: h = " + std::to_string(h) + " must divide 3 m (3 / h a whole number)");
  Analysis an = baseAnalysis(p);
  an.mesh = formCoord2D(n + 2, n + 4, (n + 2) * h, (n + 4) * h);
  const double x0 = h, y0 = h, x1 = x0 + L, y1 = y0 + L, xc = x0 + L / 2;
  const double delta = p.delta;
  addBoundary(an, {{x0, y0}, {x1, y0}}, BoundaryType::Fixed, delta);            // base
  addBoundary(an, {{x1, y0}, {x1, y1}}, BoundaryType::Roller, delta);           // right side
  addBoundary(an, {{xc + B / 2, y1}, {xc - B / 2, y1}}, BoundaryType::Prescribed, delta)
      .du = {Vector2d(0, -push / an.lstps)};                                    // the footing
  addBoundary(an, {{x0, y1}, {x0, y0}}, BoundaryType::Roller, delta);           // left side
  ibSettings(an, p);
  fillPolygon(an.mpData, Vector2d(x0, y0), n, n, an.mesh.h, p, 0.0, solidPolygon(boundariesOf(an)));
  an.afterStep = [push](Analysis& a, int lstp, double lf) {
    Vector2d sum = Vector2d::Zero();
    for (const Vector2d& f : a.ibForce) sum += f;
    a.history.push_back({{"lstp", lstp}, {"settlement", push * lf},
                         {"load_kN", -a.ibForce[2](1) / 1e3}, {"imbalance", sum.norm()}});
  };
  return an;
}

Results results(const Analysis& an, const Footing&) {
  if (an.history.empty()) return {};
  double imbalance = 0;
  for (const auto& row : an.history) imbalance = std::max(imbalance, row[3].second);
  return {{"settlement", an.history.back()[1].second}, {"load_kN", an.history.back()[2].second},
          {"imbalance_N", imbalance}, {"points", double(an.mpData.size())}};
}

// this setup's line in the table of setups/setups.cpp
SetupCalls calls() { return {params, setupGrid, results}; }

}  // namespace ample::footing
