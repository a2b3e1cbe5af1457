//--------------------------------------------------------------------------
// geostatic — the initial K0 stress of a body under gravity, in balance with its weight
//--------------------------------------------------------------------------
// See geostatic.h for the equations, inputs and outputs.
//--------------------------------------------------------------------------
#include "geostatic.h"
#include "ample/errors.h"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace ample {

Vector6d elasticStrainOf(const Vector6d& sigma, double E, double nu) {
  const double tr = sigma(0) + sigma(1) + sigma(2), G = E / (2 * (1 + nu));
  Vector6d eps;
  for (int i = 0; i < 3; ++i) eps(i) = ((1 + nu) * sigma(i) - nu * tr) / E;
  for (int i = 3; i < 6; ++i) eps(i) = sigma(i) / G;
  return eps;
}

// the top of a point's domain: y + lp_y (GIMP), y + sqrt(V) / 2 otherwise
static double domainTop(const MaterialPoint& mp) {
  return mp.mpC(1) + (mp.mpType == MpType::GIMP ? mp.lp(1) : 0.5 * std::sqrt(mp.vp));
}

// the column of grid cells a point's centre lies in
static int columnOf(const Mesh& mesh, const MaterialPoint& mp) {
  const int c = int(std::floor((mp.mpC(0) - mesh.origin(0)) / mesh.h(0)));
  return std::min(std::max(c, 0), mesh.nelsx - 1);
}

static void checkGeostatic(const Analysis& an) {
  if (!(an.g > 0))
    throw InputError("geostatic=on: the setup " + an.name + " has no gravity (g = 0): there is no weight for "
                     "the initial stress to carry; use geostatic=off (or g > 0 where the setup has g)");
  if (!an.mesh.regular())
    throw InputError("geostatic=on needs the regular grid (the surface above a point is found in its column "
                     "of cells); " + an.name + " has a general mesh");
}

// a von Mises point beyond yield: refused, naming K0 and the K0 range of this body
static void checkYield(const Analysis& an, const std::vector<double>& depth) {
  const double c = std::sqrt(2.0 / 3.0);
  double m = INFINITY;                         // |1 - K0| allowed by the weakest point
  int beyond = 0, worst = -1;
  for (size_t p = 0; p < an.mpData.size(); ++p) {
    const MaterialPoint& mp = an.mpData[p];
    if (mp.cmType != CmType::VonMises) continue;
    const double sv = mp.mpM / mp.vp0 * an.g * depth[p];   // |sigma_yy|
    if (sv <= 0) continue;
    const double limit = mp.mCst.rhoY / (c * sv);
    if (limit < m) m = limit, worst = int(p);
    if (c * std::abs(1 - an.K0) * sv > mp.mCst.rhoY) ++beyond;
  }
  if (beyond == 0) return;
  const MaterialPoint& w = an.mpData[worst];
  char msg[600];
  std::snprintf(msg, sizeof msg, "K0=%g puts the initial stress of %d von Mises points beyond yield (rho = "
                "sqrt(2/3) |1 - K0| rho g d > rho_y; the first to yield at (%g, %g), depth %g m, rho_y = %g Pa): "
                "K0 must lie in [%.4g, %.4g] for this body (allowed [0, 10]), or use cmType=elastic",
                an.K0, beyond, w.mpC(0), w.mpC(1), depth[worst], w.mCst.rhoY, std::max(0.0, 1 - m),
                std::min(10.0, 1 + m));
  throw InputError(msg);
}

void applyGeostatic(Analysis& an) {
  checkGeostatic(an);
  std::vector<double> top(an.mesh.nelsx, -INFINITY), depth(an.mpData.size());
  for (const MaterialPoint& mp : an.mpData) {
    double& t = top[columnOf(an.mesh, mp)];
    t = std::max(t, domainTop(mp));
  }
  for (size_t p = 0; p < an.mpData.size(); ++p)
    depth[p] = std::max(0.0, top[columnOf(an.mesh, an.mpData[p])] - an.mpData[p].mpC(1));
  checkYield(an, depth);
  for (size_t p = 0; p < an.mpData.size(); ++p) {
    MaterialPoint& mp = an.mpData[p];
    const double sv = -mp.mpM / mp.vp0 * an.g * depth[p];
    Vector6d sigma = Vector6d::Zero();
    sigma << an.K0 * sv, sv, an.K0 * sv, 0, 0, 0;
    mp.sig = sigma;                                          // F = I: Cauchy = Kirchhoff
    mp.epsE = mp.epsEn = elasticStrainOf(sigma, mp.mCst.E, mp.mCst.nu);
  }
}

Eigen::VectorXd selfWeight(int nDoF, double g, const std::vector<MaterialPoint>& mpData) {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(nDoF);
  for (const MaterialPoint& mp : mpData)
    for (int v = 0; v < mp.nn; ++v) w(dof(mp.nIN[v], 1)) -= mp.Svp[v] * mp.mpM * g;
  return w;
}

}  // namespace ample
