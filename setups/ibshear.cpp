//--------------------------------------------------------------------------
// ibshear — simple shear of a body that a fixed implicit boundary holds anywhere in a
//           cell ([Boundaries] sec 5.3, fig 16)
//--------------------------------------------------------------------------
// A 100 x 100 mm body (L = 0.1 m) in a grid of two 100 mm cells side by side
// (2 x 1 cells, 0.2 x 0.1 m), from x = xA to xA + L. Its 20 x 20 standard MPM
// points are 5 mm squares of the body itself (fillBlock over the body as one
// cell with mp = 20; they move with xA, so the cells hold 20 (100 - xA)/100 and
// 20 xA/100 columns). Left side x = xA: Fixed implicit boundary (u = 0). Right
// side x = xA + L: Prescribed implicit boundary, du = (0, dv) (10 mm) in one load
// step. Top and bottom (y = 0 and L, grid lines): u_x = 0 on the nodes
// (fixDofs), u_y free; with one cell in y every node is on them, so only the
// u_y of the (4 or 6) linked nodes are free. Small strain (formulation SS),
// E = 1000 MPa, nu = 0.3, delta = 1e-6 h (h = 100 mm: delta = 1e-4 mm).
// Exact: simple shear u_y = gamma (x - xA), gamma = dv / L = 0.1, u_x = 0,
// sigma_xy = mu gamma = E / (2 (1 + nu)) gamma = 38.46 MPa (the paper's
// E / (1 + nu) eps_xy with the tensor eps_xy = gamma / 2), sigma_xx = sigma_yy = 0.
// The field is linear in x, so the bilinear grid holds it exactly: the error is
// that of the implicit boundaries alone.
// Outputs: results: r_sxy (eq 30 over the domain, volume weighted), r_sxy_max
//          (the largest at a point), ru (eq 29), sxy_mean_MPa, points
// Tests:   tests/test_ibSetups.cpp
//--------------------------------------------------------------------------
#include "formCoord2D.h"
#include "setupHelpers.h"
#include <algorithm>
#include <cmath>

namespace ample::ibshear {

static const double L = 0.1;  // side of the body and of the cells (m)

// the parameters and their defaults (their ranges and help: params)
struct Ibshear : IbCommon {
  double xA = 0.0, dv = 0.01;
  Ibshear() {
    lstps = 1;
    mp = 20;
  }
};

Params params(Ibshear& p) {
  Params P = ibCommonParams(p);
  // the grid is one body high: the sheared points leave it after step 1
  P.named("lstps").integer(1, 1)
      .help("load steps: one (the sheared body's top points leave the one-cell-high grid)");
  P.named("mp").help("material points across the body in each direction (the paper: 20)");
  param(P, "xA", p.xA).range(0, L)
      .help("position of the fixed left side in the two 100 mm cells (m), 0 to 0.1");
  param(P, "dv", p.dv).range(-0.05, 0.05).help("shear displacement of the right side (m)");
  return P;
}

Analysis setupGrid(const Ibshear& p) {
  const double xA = p.xA, delta = p.delta;
  Analysis an = baseAnalysis(p);
  an.mesh = formCoord2D(2, 1, 2 * L, L);
  fixDofs(an.mesh, 0, [&](double, double Y) { return Y < 1e-9 * L || Y > L * (1 - 1e-9); });
  addBoundary(an, {{xA, L}, {xA, 0.0}}, BoundaryType::Fixed, delta);          // left: solid at x > xA
  addBoundary(an, {{xA + L, 0.0}, {xA + L, L}}, BoundaryType::Prescribed, delta).du = {{0.0, p.dv}};
  ibSettings(an, p);
  fillBlock(an.mpData, Vector2d(xA, 0.0), 1, 1, Vector2d(L, L), p, 0.0);    // the body's points
  return an;
}

Results results(const Analysis& an, const Ibshear& p) {
  const double E = p.E, nu = p.nu, xA = p.xA;
  const double gamma = p.dv / L, sxy = E / (2 * (1 + nu)) * gamma;
  double V = 0, r = 0, rMax = 0, ru = 0, mean = 0;
  for (const MaterialPoint& mp : an.mpData) {
    const double e = std::abs(mp.sig(3) - sxy) / std::abs(sxy);    // eq 30 at the point
    const Vector2d ue(0.0, gamma * (mp.X0(0) - xA));
    V += mp.vp;
    r += mp.vp * e;
    rMax = std::max(rMax, e);
    ru += mp.vp * (mp.u - ue).norm() / ue.norm();                   // eq 29
    mean += mp.vp * mp.sig(3);
  }
  Results res{{"r_sxy", r / V}, {"r_sxy_max", rMax}, {"ru", ru / V}, {"sxy_mean_MPa", mean / V / 1e6},
              {"points", double(an.mpData.size())}};
  if (gamma == 0)                                                   // no load: 0 / 0
    for (int k = 0; k < 3; ++k) {
      res[k].second = NAN;
      res.undefined(res[k].first, "no load (dv = 0): the error is relative to the exact shear 0");
    }
  return res;
}

// this setup's line in the table of setups/setups.cpp
SetupCalls calls() { return {params, setupGrid, results}; }

}  // namespace ample::ibshear
