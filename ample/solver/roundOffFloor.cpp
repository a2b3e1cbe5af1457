//--------------------------------------------------------------------------
// roundOffFloor — the level below which eq 35's residual cannot fall
//--------------------------------------------------------------------------
// See roundOffFloor.h for the derivation (steps 1-4), inputs and outputs.
//--------------------------------------------------------------------------
#include "roundOffFloor.h"
#include <algorithm>
#include <cfloat>
#include <cmath>

namespace ample {

double roundOffFloor(const std::vector<MaterialPoint>& mpData, const Eigen::VectorXd& uvw,
                     const Eigen::VectorXd& load) {
  const double u = DBL_EPSILON / 2;                            // unit roundoff (round to nearest)
  Eigen::VectorXd noise2 = Eigen::VectorXd::Zero(uvw.size());  // per dof, in units of u^2
  for (const MaterialPoint& mp : mpData) {
    double s = 0.0;                                            // step 1: the terms of grad du
    for (int i = 0; i < nD; ++i)
      for (int j = 0; j < nD; ++j) {
        double terms = 0.0;
        for (int v = 0; v < mp.nn; ++v) terms += std::abs(uvw(dof(mp.nIN[v], i)) * mp.dSvp(j, v));
        s = std::max(s, terms);
      }
    const double E = mp.mCst.E, nu = mp.mCst.nu;              // step 2: the stress
    const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
    const double dsig = M * (s + 1.0) + mp.sig.cwiseAbs().maxCoeff();
    for (int v = 0; v < mp.nn; ++v) {                          // step 3: the nodal forces
      const double f = mp.vp * mp.dSvp.col(v).cwiseAbs().sum() * dsig;
      for (int i = 0; i < nD; ++i) noise2(dof(mp.nIN[v], i)) += f * f;
    }
  }
  return u * std::sqrt(noise2.sum()) / (load.array() + DBL_EPSILON).matrix().norm();  // step 4
}

}  // namespace ample
