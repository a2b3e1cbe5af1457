// Tests of the fast point loop against the plain ones, pass by pass: detMPsFast (the
// unrolled sums of ample/fast/addPoint) against detMPs (UL, the core) and detMPsForm (PC,
// SS) on the points of several setups: MPM, GIMP, CPDI1 and CPDI2 points, a grid and a
// triangle mesh, elastic and von Mises with every point on the yield surface, each point
// with a converged state (Fn, eps_e,n) of its own. The two compute the same equations
// with different sums (G' A G against the products g_jkl; a 3 x 3 spectral decomposition
// against the closed-form in-plane one), so they agree to round-off: asked within 1e-12
// relative, in fint, in Kt and in every point's stress, for three passes of one step
// (the fast loop's plan kept between them, as in a run).
#include "ample/cpdi/elemMPinfoCPDI.h"
#include "ample/meshes/elemMPinfoMesh.h"
#include "ample/elemMPinfo.h"
#include "ample/fast/detMPsFast.h"
#include "ample/formulations/detMPsForm.h"
#include "testProblems.h"
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>

using namespace ample;

namespace {

struct Case {
  const char* setup;
  std::vector<std::pair<std::string, double>> set;
};

// the setup's points with their basis, a converged state, and (von Mises) a yield
// strength low enough that a strain of 1e-3 yields
Analysis pointsOf(const Case& c) {
  const Setup* s = findSetup(c.setup);
  REQUIRE(s != nullptr);
  Params P = s->params();
  for (const auto& kv : c.set) setParam(P, kv.first, kv.second);
  Analysis an = s->setupGrid(P);
  testing::prestrain(an.mpData, 13);
  for (MaterialPoint& mp : an.mpData)
    if (mp.cmType == CmType::VonMises) mp.mCst.rhoY = 1e-4 * mp.mCst.E;
  const bool cpdi = std::any_of(an.mpData.begin(), an.mpData.end(), [](const MaterialPoint& mp) { return isCPDI(mp); });
  if (cpdi) elemMPinfoCPDI(an.mesh, an.mpData, false);           // the basis loop the program chooses
  else if (!an.mesh.regular()) elemMPinfoMesh(an.mesh, an.mpData, false);
  else elemMPinfo(an.mesh, an.mpData);
  return an;
}

// the largest stress difference of two sets of points, relative to the largest stress
double stressDifference(const std::vector<MaterialPoint>& a, const std::vector<MaterialPoint>& b) {
  double d = 0.0, scale = 0.0;
  for (size_t p = 0; p < a.size(); ++p) {
    d = std::max(d, (a[p].sig - b[p].sig).cwiseAbs().maxCoeff());
    scale = std::max(scale, a[p].sig.cwiseAbs().maxCoeff());
  }
  return d / scale;
}

// the points on the yield surface: sqrt(2 J2) of the Kirchhoff stress = rho_y
int onSurface(const std::vector<MaterialPoint>& mpData) {
  int n = 0;
  for (const MaterialPoint& mp : mpData) {
    const Vector6d tau = mp.sig * mp.F.determinant();
    const double p = tau.head<3>().sum() / 3.0;
    const double rho = std::sqrt((tau.head<3>().array() - p).square().sum() + 2.0 * tau.tail<3>().squaredNorm());
    n += std::abs(rho - mp.mCst.rhoY) <= 1e-10 * mp.mCst.rhoY;
  }
  return n;
}

}  // namespace

TEST_SUITE("pointLoops") {
  TEST_CASE("detMPsFast: fint, Kt and the stresses of every pass within 1e-12 of detMPs (UL) and detMPsForm (PC, SS), on the points of six setups") {
    const std::vector<Case> cases = {
        {"compaction", {{"nelsy", 8}}},                                   // GIMP, elastic
        {"collapse", {{"a", 1}}},                                         // GIMP, von Mises
        {"collapse", {{"a", 1}, {"mpType", 4}}},                          // CPDI2, von Mises
        {"shear", {{"mpType", 3}, {"cmType", 2}}},                        // CPDI1, von Mises
        {"beam", {{"a", 1}, {"mpType", 1}}},                              // MPM, elastic
        {"annulus", {}},                                                  // MPM on triangles, elastic
    };
    for (size_t k = 0; k < cases.size(); ++k)
      for (Formulation form : {Formulation::UL, Formulation::PC, Formulation::SS}) {
        const Case& c = cases[k];
        CAPTURE(k);
        CAPTURE(int(form));
        const Analysis an = pointsOf(c);
        const bool plastic = an.mpData[0].cmType == CmType::VonMises;
        const Eigen::VectorXd uvw = testing::randomUvw(an, 0.02 * std::sqrt(an.mpData[0].vp0), 3);
        std::vector<MaterialPoint> plainPts = an.mpData, fastPts = an.mpData;
        DetMPsOut plain, fast;                                          // kept over the passes
        for (double pass : {0.25, 0.5, 1.0}) {
          CAPTURE(pass);
          pointLoopOf(form)(pass * uvw, plainPts, form, plain);
          detMPsFast(pass * uvw, fastPts, form, fast);
          REQUIRE(fast.plan);                                           // the fast loop ran
          if (plastic && pass == 1.0) CHECK(onSurface(plainPts) == int(plainPts.size()));
          CHECK(plain.fint.norm() > 0.0);
          CHECK((fast.fint - plain.fint).norm() <= 1e-12 * plain.fint.norm());
          CHECK((fast.Kt - plain.Kt).norm() <= 1e-12 * plain.Kt.norm());
          CHECK(stressDifference(fastPts, plainPts) <= 1e-12);
        }
      }
  }
}
