//--------------------------------------------------------------------------
// compaction — elastic column compacting under its own weight ([AMPLE] sec 5.1)
//--------------------------------------------------------------------------
// Column of height l0 = 50 m, one square cell wide (nelsx = 1), nelsy cells
// high, E = 10 kPa, nu = 0, rho = 80 kg/m3, g = 10 m/s2 over 40 load steps,
// mp x mp points per cell (2 x 2), rollers on the base and both sides.
// Analytic stress (eq 36): sigma_yy = -rho g (l0 - Y), Y the original height;
// error (eq 37) = sum_p |sigma_yy,p - sigma_yy(Y_p)| V0_p / (rho g l0 V0).
//   ample compaction nelsy=256 mpType=1     # standard MPM, 256 cells
// Outputs: Analysis (mesh, mpData, lstps, g) · results: error (eq 37)
// Tests:   tests/test_setups.cpp (eq 36 / 37 values), tests/test_ample.cpp, tests/test_output.cpp
//--------------------------------------------------------------------------
#include "formCoord2D.h"
#include "setupHelpers.h"
#include <cmath>

namespace ample::compaction {

// the parameters and their defaults (their ranges and help: params)
struct Compaction : Common {
  int nelsy = 64;
  double l0 = 50, rho = 80, g = 10;
  Compaction() {
    lstps = 40;
    E = 10e3;
    nu = 0.0;
  }
};

// each parameter's name on the command line, bound to its member, with its range and help
Params params(Compaction& p) {
  Params P = commonParams(p);
  param(P, "nelsy", p.nelsy).integer(1, 1 << 22).help("cells over the column height");
  param(P, "l0", p.l0).above(0).help("column height (m)");
  param(P, "rho", p.rho).atLeast(0).help("density (kg/m3)");
  param(P, "g", p.g).atLeast(0).help("gravitational acceleration (m/s2)");
  return P;
}

Analysis setupGrid(const Compaction& p) {
  const int nelsy = p.nelsy;
  const double l0 = p.l0, lx = l0 / nelsy;  // one square cell wide
  Analysis an = baseAnalysis(p);
  an.g = p.g;
  an.mesh = formCoord2D(1, nelsy, lx, l0);
  const double eps = 1e-9 * lx;
  fixDofs(an.mesh, 0, [&](double X, double) { return X < eps || X > lx - eps; });  // sides
  fixDofs(an.mesh, 1, [&](double, double Y) { return Y < eps; });                   // base
  fillBlock(an.mpData, Vector2d::Zero(), 1, nelsy, an.mesh.h, p, p.rho);
  return an;
}

Results results(const Analysis& an, const Compaction& p) {
  const double l0 = p.l0, rho = p.rho, g = p.g;
  double V0 = 0.0, err = 0.0;
  for (const MaterialPoint& mp : an.mpData) {
    const double sigA = -rho * g * (l0 - mp.X0(1));  // eq 36
    err += std::abs(mp.sig(1) - sigA) * mp.vp0;
    V0 += mp.vp0;
  }
  Results r{{"error", err / (rho * g * l0 * V0)}};  // eq 37
  if (rho * g == 0) {                                // no load: eq 37 is 0 / 0
    r[0].second = NAN;
    r.undefined("error", "no load (rho g = 0): eq 37 divides by rho g l0");
  }
  return r;
}

// this setup's line in the table of setups/setups.cpp
SetupCalls calls() { return {params, setupGrid, results}; }

}  // namespace ample::compaction
