//--------------------------------------------------------------------------
// shear — simple shear of a unit square ([Lagrangian] sec 7.2)
//--------------------------------------------------------------------------
// Unit square, h = 1 m / nels (0.125 m), mp x mp points per cell (3 x 3),
// E = 10 kPa, nu = 0.3, no gravity; the top is sheared by dl = 6 m over 30
// displacement-controlled load steps. The homogeneous field du = (dl/lstps) Y,
// dv = 0 is imposed at the start of each step (beforeStep) on the nodes of the
// cells linked to the outer layer of points (prescribe=boundary, the default:
// the paper's "all of the background cells that contained the outer boundary
// of material points"; the interior nodes are solved for), or on every active
// node (prescribe=all: nothing is left to solve, a test of the model alone).
// The paper's reading gives the homogeneous stress at every point for MPM, GIMP
// with every update but Uii, CPDI1 and CPDI2: the rows of points stay uniform,
// so the interior nodes are in balance under the homogeneous stress (MPM needs
// the round-off tolerance of elemForMP/SvpMPM: points land on grid lines).
// GIMP default here: domainUpdate=FiiVol (eq 38), which keeps the domains of
// simple shear unchanged (F11 = F22 = det F = 1). The program-wide default Uii
// (eq 34) is the paper's failing case (sec 7.2): U22 > 1 (U11 < 1), the top and
// bottom domains leave the grid [0, 1] in y and lose the partition of unity
// (error 0.86, no convergence in step 27; with prescribe=all 0.87).
// Reference: one point driven by F = [1 gamma; 0 1] through the same model
// (homogeneous.h): elastic (cmType 1) or von Mises with rho_y = 5 kPa (2).
//   ample shear mpType=CPDI2 cmType=VM
// Outputs: results: error = max_p |sigma_p - sigma_ref| / |sigma_ref| at the
//          last step; history.csv: lstp, gamma, mean and reference sigma_xy, error
// Tests:   tests/test_ample.cpp (against closed forms written in the test)
//--------------------------------------------------------------------------
#include "ample/cpdi/elemMPinfoCPDI.h"
#include "formCoord2D.h"
#include "homogeneous.h"
#include "setupHelpers.h"
#include <cmath>

namespace ample::shear {

// the parameters and their defaults (their ranges and help: params)
struct Shear : Common {
  int nels = 8;
  double dl = 6;
  int prescribe = 1;                           // 1 boundary, 2 all
  Shear() {
    lstps = 30;
    mp = 3;
    E = 10e3;
    nu = 0.3;
    rhoY = 5e3;
    domainUpdate = DomainUpdate::FiiVol;       // eq 38: unchanged domains under simple shear
  }
};

Params params(Shear& p) {
  Params P = commonParams(p);
  param(P, "nels", p.nels).integer(1, 256).help("cells across the unit square: h = 1 m / nels");
  param(P, "dl", p.dl).range(0, 50).help("shear displacement of the top (m)");
  P.named("domainUpdate")
      .help("GIMP domain update ([Lagrangian] eqs 32-39); shear default FiiVol (eq 38); Uii (eq 34, "
            "the default of the other setups) is the paper's failing case: error 0.86, stops in step 27");
  param(P, "prescribe", p.prescribe).choice(1, {"boundary", "all"})
      .help("nodes given the shear: of the cells linked to the outer layer of points (the paper's, "
            "interior nodes solved for), or of all active cells (nothing solved: tests the model only)");
  return P;
}

// Cauchy stress of one point after lstp steps of simple shear (J = 1: Cauchy = Kirchhoff)
static Vector6d reference(const MaterialPoint& mp, int lstp, double dg) {
  Matrix3d dF = Matrix3d::Identity();
  dF(0, 1) = dg;
  Vector6d epsE = Vector6d::Zero(), tau = Vector6d::Zero();
  for (int s = 0; s < lstp; ++s) tau = homogeneousStep(dF, epsE, mp.mCst, mp.cmType);
  return tau;
}

static double maxError(const Analysis& an, const Vector6d& ref) {
  double err = 0.0;
  for (const MaterialPoint& mp : an.mpData) err = std::max(err, (mp.sig - ref).norm() / ref.norm());
  return err;
}

Analysis setupGrid(const Shear& p) {
  const int nels = p.nels;
  const double dl = p.dl, dg = dl / p.lstps;                    // shear per step
  const int nx = nels * (int(std::ceil(dl)) + 2);               // room for the top to move
  Analysis an = baseAnalysis(p);
  an.mesh = formCoord2D(nx, nels, double(nx) / nels, 1.0);
  fillBlock(an.mpData, Vector2d::Zero(), nels, nels, an.mesh.h, p, 0.0);
  const double edge = 1.0 / (nels * p.mp);                      // the outer layer of points
  for (int i = 0; i < int(an.mpData.size()); ++i) {
    const Vector2d X = an.mpData[i].X0;
    if (X.minCoeff() < edge || X.maxCoeff() > 1.0 - edge || p.prescribe == 2)
      an.tagged.push_back(i);
  }
  an.beforeStep = [dg](Analysis& a, int) {                      // shear the boundary cells
    elemMPinfoCPDI(a.mesh, a.mpData);
    std::vector<char> fixed(a.mesh.nodes(), 0);
    for (int p : a.tagged)
      for (int e = 0; e < a.mpData[p].ne; ++e)
        for (int c = 0; c < nen; ++c) fixed[a.mesh.etpl(a.mpData[p].eIN[e], c)] = 1;
    a.mesh.bc.clear();
    for (int n = 0; n < a.mesh.nodes(); ++n)
      if (fixed[n]) a.mesh.bc.insert(a.mesh.bc.end(), {{dof(n, 0), dg * a.mesh.coord(n, 1)}, {dof(n, 1), 0.0}});
  };
  an.afterStep = [dg](Analysis& a, int lstp, double /*lf: gamma = lstp x dg*/) {
    const Vector6d ref = reference(a.mpData[0], lstp, dg);
    double sxy = 0.0;
    for (const MaterialPoint& mp : a.mpData) sxy += mp.sig(3) / a.mpData.size();
    a.history.push_back({{"lstp", lstp}, {"gamma", dg * lstp}, {"sxy_mean", sxy},
                         {"sxy_reference", ref(3)}, {"error", maxError(a, ref)}});
  };
  return an;
}

Results results(const Analysis& an, const Shear&) {
  if (an.history.empty()) return {};
  return {{"error", an.history.back().back().second}, {"sxy", an.history.back()[2].second},
          {"sxy_reference", an.history.back()[3].second}};
}

// this setup's line in the table of setups/setups.cpp
SetupCalls calls() { return {params, setupGrid, results}; }

}  // namespace ample::shear
