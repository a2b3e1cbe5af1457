//--------------------------------------------------------------------------
// stretch — plane-strain stretch of a 2 x 2 von Mises block ([CPDI] sec 3.1)
//--------------------------------------------------------------------------
// E = 1000, nu = 0, rho_c = 400 (rhoY), 2 x 2 cells with mp x mp = 2 x 2
// points each, rollers on the bottom and the left; the right side is pulled
// du = 0.2 per load step for 20 steps. As in the paper the grid follows the
// body ("moving mesh"): at the start of each step it is rebuilt over the
// current length L = L0 + (lstp - 1) du, so that the pulled side stays on
// grid nodes (beforeStep). Reference: the homogeneous state of one point with
// sigma_yy = 0 (free top), found step by step (homogeneous.h); reaction
// R = tau_xx L0 / lambda_x (Cauchy stress times current height, unit thickness).
//   ample stretch mpType=CPDI2
// Outputs: results: reaction at the last step, its reference and the largest
//          difference over the steps relative to the largest reference;
//          history.csv: lstp, reaction, reference
// Tests:   tests/test_ample.cpp (against closed forms written in the test)
//--------------------------------------------------------------------------
#include "formCoord2D.h"
#include "homogeneous.h"
#include "setupHelpers.h"
#include <cmath>

namespace ample::stretch {

// the parameters and their defaults (their ranges and help: params)
struct Stretch : Common {
  double du = 0.2;
  Stretch() {
    lstps = 20;
    cmType = CmType::VonMises;
    E = 1000;
    nu = 0.0;
    rhoY = 400;
  }
};

Params params(Stretch& p) {
  Params P = commonParams(p);
  param(P, "du", p.du).range(0, 10).help("displacement of the right side per step");
  return P;
}

// reaction of the homogeneous solution after each of n steps (top free: sigma_yy = 0)
static std::vector<double> reference(const MaterialPoint& mp, int n, double L0, double du) {
  std::vector<double> R;
  Vector6d epsE = Vector6d::Zero();
  for (int s = 1; s <= n; ++s) {
    Matrix3d dF = Matrix3d::Identity();
    dF(0, 0) = (L0 + s * du) / (L0 + (s - 1) * du);
    double lo = 0.2, hi = 2.0;  // bisection on the vertical stretch of the step
    for (int it = 0; it < 200; ++it) {
      dF(1, 1) = 0.5 * (lo + hi);
      Vector6d e = epsE;
      (homogeneousStep(dF, e, mp.mCst, mp.cmType)(1) > 0 ? hi : lo) = dF(1, 1);
    }
    const Vector6d tau = homogeneousStep(dF, epsE, mp.mCst, mp.cmType);
    R.push_back(tau(0) * L0 / ((L0 + s * du) / L0));
  }
  return R;
}

static void grid(Analysis& an, double L, double L0) {  // grid over the current body
  an.mesh = formCoord2D(2, 2, L, L0);
  const double eps = 1e-9 * L;
  fixDofs(an.mesh, 0, [&](double X, double) { return X < eps; });
  fixDofs(an.mesh, 1, [&](double, double Y) { return Y < eps; });
}

Analysis setupGrid(const Stretch& p) {
  const double L0 = 2.0, du = p.du;
  Analysis an = baseAnalysis(p);
  grid(an, L0, L0);
  fillBlock(an.mpData, Vector2d::Zero(), 2, 2, an.mesh.h, p, 0.0);
  an.gridMoves = true;                                          // mesh_<lstp>.vtk each step
  an.beforeStep = [=](Analysis& a, int lstp) {
    grid(a, L0 + (lstp - 1) * du, L0);
    const double eps = 1e-9 * L0;
    fixDofs(a.mesh, 0, [&](double X, double) { return X > L0 + (lstp - 1) * du - eps; }, du);
  };
  an.afterStep = [=](Analysis& a, int lstp, double /*lf: stretch = lstp x du*/) {
    double R = 0.0;  // sum of the x reactions on the pulled side
    for (const BC& c : a.mesh.bc)
      if (c.value != 0.0) R += a.frct(c.dof);
    const std::vector<double> ref = reference(a.mpData[0], lstp, L0, du);
    a.history.push_back({{"lstp", lstp}, {"reaction", R}, {"reference", ref.back()}});
  };
  return an;
}

Results results(const Analysis& an, const Stretch&) {
  if (an.history.empty()) return {};
  double diff = 0.0, refMax = 0.0;
  for (const auto& row : an.history) {
    diff = std::max(diff, std::abs(row[1].second - row[2].second));
    refMax = std::max(refMax, std::abs(row[2].second));
  }
  Results r{{"reaction", an.history.back()[1].second}, {"reference", an.history.back()[2].second},
            {"max_rel_difference", diff / refMax}};
  if (refMax == 0) {                                             // no load: 0 / 0
    r[2].second = NAN;
    r.undefined("max_rel_difference", "no load (du = 0): the reference reaction is 0");
  }
  return r;
}

// this setup's line in the table of setups/setups.cpp
SetupCalls calls() { return {params, setupGrid, results}; }

}  // namespace ample::stretch
