//--------------------------------------------------------------------------
// collapse — von Mises block collapsing under self weight ([AMPLE] sec 5.3)
//--------------------------------------------------------------------------
// Half of a 16 m x 8 m block (8 m x 8 m, symmetry on x = 0) in a 16 m x 8 m
// grid, h = 2 m / a, mp x mp GIMP points per cell, E = 1 MPa, nu = 0.3,
// rho_y = 20 kPa, unit weight 10 kN/m3 (rho = 1000, g = 10) over 40 load
// steps, rollers on the base and on the left edge.
//   ample collapse a=2 mp=3     # h = 1 m, [AMPLE] table 5: 13.781 / 6.194
// Outputs: Analysis · results: final extent and height, measured to the edge
//          of the point domains max(x + lpx), max(y + lpy) (GIMP) or to the
//          centres plus the initial half spacing h/(2 mp) (MPM, [Lagrangian] table 6)
// Tests:   tests/test_ample.cpp
//--------------------------------------------------------------------------
#include "formCoord2D.h"
#include "setupHelpers.h"
#include <cmath>

namespace ample::collapse {

// the parameters and their defaults (their ranges and help: params)
struct Collapse : Common {
  int a = 2;
  double width = 16;
  int supports = 1;
  double rho = 1000, g = 10;
  Collapse() {
    lstps = 40;
    mp = 3;
    cmType = CmType::VonMises;
    E = 1e6;
    nu = 0.3;
    rhoY = 20e3;
  }
};

Params params(Collapse& p) {
  Params P = commonParams(p);
  param(P, "a", p.a).integer(1, 64).help("grid refinement: h = 2 m / a");
  param(P, "width", p.width).above(8).atMost(1000)
      .help("grid width (m), rounded up to whole cells; below ~14 m the toe leaves the grid");
  param(P, "supports", p.supports).integer(0, 1)
      .help("rollers on base and left edge (1), or none (0: a rigid-body mode, for testing)");
  param(P, "rho", p.rho).atLeast(0).help("density (kg/m3)");
  param(P, "g", p.g).atLeast(0).help("gravitational acceleration (m/s2)");
  return P;
}

Analysis setupGrid(const Collapse& p) {
  const int a = p.a;
  Analysis an = baseAnalysis(p);
  an.g = p.g;
  const int nelsx = int(std::ceil(p.width * a / 2.0 - 1e-9));  // h = 2 m / a
  an.mesh = formCoord2D(nelsx, 4 * a, nelsx * 2.0 / a, 8);
  if (p.width < 1000) an.widerGrid = "width=" + number(std::min(1000.0, 2 * p.width));
  const double eps = 1e-9 * an.mesh.h(0);
  if (p.supports == 1) {
    fixDofs(an.mesh, 0, [&](double X, double) { return X < eps; });  // left edge
    fixDofs(an.mesh, 1, [&](double, double Y) { return Y < eps; });  // base
  }
  fillBlock(an.mpData, Vector2d::Zero(), 4 * a, 4 * a, an.mesh.h, p, p.rho);
  return an;
}

Results results(const Analysis& an, const Collapse& p) {
  const double half = an.mesh.h(0) / (2.0 * p.mp);  // initial half spacing
  double ext = -INFINITY, hgt = -INFINITY, xMax = -INFINITY, yMax = -INFINITY;
  for (const MaterialPoint& mp : an.mpData) {
    const Vector2d l = (mp.mpType == MpType::MPM) ? Vector2d(half, half) : mp.lp;
    ext = std::max(ext, mp.mpC(0) + l(0));
    hgt = std::max(hgt, mp.mpC(1) + l(1));
    xMax = std::max(xMax, mp.mpC(0));
    yMax = std::max(yMax, mp.mpC(1));
  }
  return {{"extent", ext}, {"height", hgt}, {"max_x", xMax}, {"max_y", yMax}};
}

// this setup's line in the table of setups/setups.cpp
SetupCalls calls() { return {params, setupGrid, results}; }

}  // namespace ample::collapse
