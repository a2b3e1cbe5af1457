//--------------------------------------------------------------------------
// ibcantilever — slender cantilever at 0, 45 and 90 degrees to the grid ([Boundaries] sec 5.4)
//--------------------------------------------------------------------------
// A 100 x 20 mm beam (L = 0.1 m, d = 0.02 m), plane strain, E = 1000 MPa,
// nu = 0.3, small strain (formulation SS, sec 2), standard MPM (mpType 1),
// mp x mp points per cell by fillPolygon (sec 4; the paper: 10 x 10), grid
// h = 2 mm. In the beam's own axes (x' along the beam, y' across it) the free
// end is x' = 0 ("the origin", its lower corner (0, 0)), the fixed end x' = L,
// the faces y' = 0 and y' = d; the end x' = L is one implicit Fixed boundary
// (u = 0, eqs 13-22). The whole model, beam, load and room to deflect, is the
// 0 degree model turned by theta (degrees, anticlockwise) about the origin,
// which sits on a grid node; multiples of 90 degrees use exact cos, sin, so
// 0 and 90 degrees are the same discretisation. The body force b (N/m3; the
// paper's 0.2 N/mm2 per unit thickness = 2e8 N/m3) acts along -y' (the
// paper's "y-directions shown in fig 17", read as the beam's own transverse
// direction so that the three problems are the same) and grows in lstps equal
// steps (default 10: with 20, the 0 and 90 degree runs meet a cell-crossing
// mechanism at step 14, docs/implicitBoundaries.md). It is carried as the point force fp = b V0 (-y' rotated), which
// detExtForce sums exactly as rho g V (eq 27): gravity (an.g) is only -y.
// A point that moves more than twice the beam-theory tip deflection (a point
// alone in a cell: the cell-crossing mechanism of standard MPM) stops the run
// with a RunError instead of a silently wrong free-end mean.
// Free-end displacement: the V-weighted mean over the points whose original
// x' < strip = 2 mm (one paper cell), in beam axes; on a coarser grid, one cell h
// (h = 0.01 m, 2 x 2 points: none within 2 mm).
// Beam theory (results, history): plane-strain Timoshenko cantilever under
// q = b d, E' = E / (1 - nu^2), I = d^3 / 12, G = E / (2 (1 + nu)), kappa = 5/6,
// at distance s = L - x' from the support:
//   w(s) = q s^2 (6 L^2 - 4 L s + s^2) / (24 E' I) + q (L s - s^2 / 2) / (kappa G d)
// (tip: q L^4 / (8 E' I) + q L^2 / (2 kappa G d)), averaged over the same points.
// Outputs: history.csv per step: b, total body force, free-end u', v', beam
//          theory v', reaction (sum of an.frct) in beam axes;
//          results: the same at full load, their ratios, points
// Tests:   tests/test_ibCantilever.cpp
//--------------------------------------------------------------------------
#include "ample/errors.h"
#include "formCoord2D.h"
#include "setupHelpers.h"
#include <cmath>
#include <cstdio>

namespace ample::ibcantilever {

static const double L = 0.1, d = 0.02, strip = 0.002;  // beam (m); free-end strip (m)

// the parameters and their defaults (their ranges and help: params)
struct Ibcantilever : IbCommon {
  double theta = 0, h = 0.002, b = 2e8;
  Ibcantilever() {
    lstps = 10;                      // 20 meet a cell-crossing mechanism (docs)
    mp = 10;                         // 10 x 10 points per cell: the paper's 100
  }
};

Params params(Ibcantilever& p) {
  Params P = ibCommonParams(p);
  param(P, "theta", p.theta).range(-360, 360)
      .help("rotation of the whole model to the grid (degrees, anticlockwise, about the free end's lower "
            "corner, a grid node); the beam runs from the free end x' = 0 to the fixed end x' = 100 mm");
  param(P, "h", p.h).range(2.5e-4, 0.01)
      .help("grid spacing (m); d / h = 0.02 / h whole keeps the 0 and 90 degree faces on grid lines");
  param(P, "b", p.b).atLeast(0)
      .help("body force at full load along the beam's own -y' (N/m3; the paper: 0.2 N/mm2 = 2e8); "
            "the free-end figures are means over the points within 2 mm of the free end");
  return P;
}

// the Timoshenko deflection (m, along -y') at x' from the free end under q = b d
static double beamTheory(double x, double b, double E, double nu) {
  const double q = b * d, Ep = E / (1 - nu * nu), I = d * d * d / 12, G = E / (2 * (1 + nu));
  const double s = L - x;
  return q * s * s * (6 * L * L - 4 * L * s + s * s) / (24 * Ep * I) + q * (L * s - s * s / 2) / (5.0 / 6 * G * d);
}

// the grid node of the origin and the grid (cells) that holds the turned room
struct Layout { Vector2d O; int nelsx, nelsy; };
// The room grows with the deflection b / E: a tip deflection above the beam's length L is
// outside small-strain beam theory and would size the grid without bound, so it is refused
// (InputError naming b and E and the values that fit).
static Layout layout(const Ibcantilever& p) {
  const double h = p.h, b = p.b, E = p.E;
  const double w = beamTheory(0, b, E, p.nu);
  if (!(w <= L)) {                                                   // (also NaN)
    char msg[400];
    std::snprintf(msg, sizeof msg, "b = %g N/m3 with E = %g Pa: beam theory's tip deflection %.3g m exceeds "
                  "the beam's length L = 0.1 m (the grid is sized from it): use b <= %.3g or E >= %.3g",
                  b, E, w, b * L / w, E * w / L);
    throw InputError(msg);
  }
  const double slope = 2 * w / L;                                    // > the tip rotation
  const double x0 = -(1.3 * slope * d + 2 * h), y0 = -(1.3 * w + 2 * h);  // room to deflect
  const Eigen::Matrix2d R = rotationDegrees(p.theta);
  Vector2d lo = Vector2d::Constant(INFINITY), hi = -lo;
  for (const Vector2d& c : {Vector2d(x0, y0), Vector2d(L + 2 * h, y0), Vector2d(L + 2 * h, d + 2 * h),
                            Vector2d(x0, d + 2 * h)}) {
    lo = lo.cwiseMin(R * c), hi = hi.cwiseMax(R * c);
  }
  const int i0 = int(std::ceil(-lo(0) / h - 1e-9)), j0 = int(std::ceil(-lo(1) / h - 1e-9));
  return {Vector2d(i0 * h, j0 * h), i0 + int(std::ceil(hi(0) / h - 1e-9)), j0 + int(std::ceil(hi(1) / h - 1e-9))};
}

Analysis setupGrid(const Ibcantilever& p) {
  const double h = p.h, b = p.b;
  const Layout g = layout(p);
  const Eigen::Matrix2d R = rotationDegrees(p.theta);
  Analysis an = baseAnalysis(p);
  an.mesh = formCoord2D(g.nelsx, g.nelsy, g.nelsx * h, g.nelsy * h);
  auto at = [&](double x, double y) { return Vector2d(g.O + R * Vector2d(x, y)); };
  const Polygon beam = {at(0, 0), at(L, 0), at(L, d), at(0, d)};     // anticlockwise
  addBoundary(an, {beam[1], beam[2]}, BoundaryType::Fixed, p.delta);  // the support
  ibSettings(an, p);
  Vector2d lo = beam[0], hi = beam[0];                               // the cells round the beam
  for (const Vector2d& c : beam) lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
  const Eigen::Vector2i c0 = (lo / h).array().floor().cast<int>() - 1;
  const Eigen::Vector2i c1 = (hi / h).array().ceil().cast<int>() + 1;
  fillPolygon(an.mpData, c0.cast<double>() * h, c1(0) - c0(0), c1(1) - c0(1), an.mesh.h, p, 0.0, beam);
  const Vector2d dir = R * Vector2d(0, -1);                          // -y'
  for (MaterialPoint& mp : an.mpData) mp.fp = b * mp.vp0 * dir;      // body force as fp (eq 27)

  const double E = p.E, nu = p.nu;
  an.afterStep = [R, O = g.O, b, E, nu, tol = an.tol](Analysis& a, int lstp, double lf) {
    Vector2d uTip = Vector2d::Zero(), F = Vector2d::Zero(), Rct = Vector2d::Zero();
    double V = 0, wTip = 0;
    const double uMax = 2 * beamTheory(0, lf * b, E, nu) + a.mesh.h(0);  // > any point's share
    for (const MaterialPoint& mp : a.mpData) {
      if (mp.u.norm() > uMax)  // a point alone in a cell on a mechanism (cell crossing)
        throw RunError("load step " + std::to_string(lstp) + ": a point at (" + std::to_string(mp.X0(0)) +
                       ", " + std::to_string(mp.X0(1)) + ") moved " + std::to_string(mp.u.norm()) +
                       " m, twice the beam-theory tip deflection: a cell-crossing mechanism; " +
                       (tol > 1e-6 ? std::string("try the paper's tol=1e-8 (a loose tol accepted it)")
                                   : a.ghost > 0 ? std::string("try mp=5 or other lstps")
                                                 : std::string("try ghost=0.01 (it pins the nodes of a point "
                                                               "alone in a cell) or mp=5")));
      F += lf * mp.fp;
      const Vector2d X = R.transpose() * (mp.X0 - O);
      if (X(0) >= std::max(strip, a.mesh.h(0))) continue;  // one cell at least: a point falls in it
      V += mp.vp0, uTip += mp.vp0 * R.transpose() * mp.u, wTip += mp.vp0 * beamTheory(X(0), lf * b, E, nu);
    }
    for (int n = 0; n < a.mesh.nodes(); ++n) Rct += Vector2d(a.frct(dof(n, 0)), a.frct(dof(n, 1)));
    F = R.transpose() * F, Rct = R.transpose() * Rct;
    a.history.push_back({{"lstp", lstp}, {"load_factor", lf}, {"b", lf * b}, {"F_y", F(1)},
                         {"tip_u", uTip(0) / V}, {"tip_v", uTip(1) / V}, {"tip_v_beam", -wTip / V},
                         {"R_x", Rct(0)}, {"R_y", Rct(1)}});
  };
  return an;
}

Results results(const Analysis& an, const Ibcantilever&) {
  if (an.history.empty()) return {{"points", double(an.mpData.size())}};
  Results r;
  for (const auto& kv : an.history.back())
    if (kv.first != "lstp" && kv.first != "load_factor") r.push_back(kv);
  const auto v = [&](const char* k) { for (const auto& kv : r) if (kv.first == k) return kv.second; return 0.0; };
  const bool load = v("F_y") != 0 && v("tip_v_beam") != 0;
  r.push_back({"tip_v_over_beam", load ? v("tip_v") / v("tip_v_beam") : NAN});
  r.push_back({"reaction_error", load ? std::abs(v("R_y") + v("F_y")) / std::abs(v("F_y")) : NAN});
  if (!load) {
    r.undefined("tip_v_over_beam", "no load (b = 0): beam theory's deflection is 0");
    r.undefined("reaction_error", "no load (b = 0): the error is relative to F_y = 0");
  }
  r.push_back({"points", double(an.mpData.size())});
  return r;
}

// this setup's line in the table of setups/setups.cpp
SetupCalls calls() { return {params, setupGrid, results}; }

}  // namespace ample::ibcantilever
