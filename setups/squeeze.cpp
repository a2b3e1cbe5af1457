//--------------------------------------------------------------------------
// squeeze — elastic block squeezed from above, sides free (the worked setup of docs/new-setup.md)
//--------------------------------------------------------------------------
// Block W x H = 1 m x 1 m (E = 10 MPa, nu = 0.3), rollers on the base (y = 0)
// and on the left (x = 0, a symmetry line), the grid nodes on the top line
// y = H moved down by `squash` x H / lstps per load step, the right side free;
// square cells h = H / nels, mp x mp points per cell, small strain (SS,
// [Boundaries] sec 2). The grid reaches `margin` cells past the right side, since
// the block grows sideways (a point that leaves the grid stops the run).
// Analytic (plane strain, sigma_xx = 0, eps_yy = -squash):
//   sigma_yy = E eps_yy / (1 - nu^2), eps_xx = -nu eps_yy / (1 - nu)
// results: error = the largest over the points of |sigma - sigma_a| / |sigma_yy,a|
// (xx, yy, xy) and |u - u_a| / |eps_yy| (u_a = (eps_xx X, eps_yy Y), H = W = 1 m);
// sigma_yy of point 0 and sigma_yy,a; the force on the top nodes and -sigma_yy,a W.
//   ample squeeze squash=0.02 mpType=MPM
// Outputs: Analysis · results · history.csv: lstp, v_top, force, force_a
// Tests:   tests/test_setups.cpp, CTest setup.squeeze (docs/new-setup.md)
//--------------------------------------------------------------------------
#include "formCoord2D.h"
#include "setupHelpers.h"
#include <algorithm>
#include <cmath>

namespace ample::squeeze {

// the parameters and their defaults (their ranges and help: params)
struct Squeeze : Common {
  int nels = 4, margin = 1;
  double squash = 0.05;
  Squeeze() {
    formulation = Formulation::SS;  // the analytic solution is exact for the grid
    E = 10e6;
    nu = 0.3;
  }
};

Params params(Squeeze& p) {
  Params P = commonParams(p);
  param(P, "nels", p.nels).integer(1, 1024).help("cells over the block height: h = 1 m / nels");
  param(P, "margin", p.margin).integer(1, 64).help("grid cells past the right side");
  param(P, "squash", p.squash).range(0, 0.5).help("top displacement / H at the last step");
  return P;
}

// plane strain, sigma_xx = 0: sigma_yy = C eps_yy with C = E / (1 - nu^2)
static double stiffness(const Squeeze& p) { return p.E / (1 - p.nu * p.nu); }

Analysis setupGrid(const Squeeze& p) {
  const double W = 1, H = 1;
  const int nels = p.nels, margin = p.margin;
  const double h = H / nels;                                     // square cells
  Analysis an = baseAnalysis(p);
  an.mesh = formCoord2D(nels + margin, nels, (nels + margin) * h, H);
  if (margin < 64) an.widerGrid = "margin=" + std::to_string(std::min(64, 2 * margin));
  const double eps = 1e-9 * h, dv = -p.squash * H / an.lstps;
  fixDofs(an.mesh, 0, [&](double X, double) { return X < eps; });      // left: symmetry
  fixDofs(an.mesh, 1, [&](double, double Y) { return Y < eps; });      // base: rollers
  fixDofs(an.mesh, 1, [&](double, double Y) { return Y > H - eps; }, dv);  // top: pushed
  fillBlock(an.mpData, Vector2d::Zero(), nels, nels, an.mesh.h, p, 1.0);
  const double C = stiffness(p), top = nels * (nels + margin + 1);  // first node of the top row
  const double squash = p.squash;
  an.afterStep = [=](Analysis& a, int lstp, double lf) {         // the force on the top
    double force = 0;
    for (int n = 0; n <= nels + margin; ++n) force += a.frct(dof(top + n, 1));
    const double vTop = -squash * H * lf;                        // the top's displacement so far
    a.history.push_back({{"lstp", lstp}, {"v_top", vTop},
                         {"force", force}, {"force_a", C * vTop / H * W}});
  };
  return an;
}

Results results(const Analysis& an, const Squeeze& p) {
  const double nu = p.nu, eYY = -p.squash, eXX = -nu * eYY / (1 - nu);
  const double sA = stiffness(p) * eYY;                          // sigma_yy,a
  const int n = an.lstps;  // SS moves the points: each step's strain acts on the moved body
  const double gX = std::pow(1 + eXX / n, n) - 1, gY = std::pow(1 + eYY / n, n) - 1;
  double err = 0;                                                // stress, then displacement
  for (const MaterialPoint& mp : an.mpData)
    err = std::max({err, std::abs(mp.sig(0)) / std::abs(sA), std::abs(mp.sig(1) - sA) / std::abs(sA),
                    std::abs(mp.sig(3)) / std::abs(sA),
                    std::abs(mp.u(0) - gX * mp.X0(0)) / std::abs(eYY),
                    std::abs(mp.u(1) - gY * mp.X0(1)) / std::abs(eYY)});
  Results r{{"error", err}, {"sigma_yy", an.mpData[0].sig(1)}, {"sigma_yy_a", sA}};
  if (sA == 0) {                                                 // no load: 0 / 0
    r[0].second = NAN;
    r.undefined("error", "no load (squash = 0): the error is relative to sigma_yy,a = 0");
  }
  if (!an.history.empty())                                       // (none when no step converged)
    r.insert(r.end(), {{"force", an.history.back()[2].second}, {"force_a", an.history.back()[3].second}});
  return r;
}

// this setup's line in the table of setups/setups.cpp
SetupCalls calls() { return {params, setupGrid, results}; }

}  // namespace ample::squeeze
