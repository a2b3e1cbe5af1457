//--------------------------------------------------------------------------
// detExtForce — nodal external forces from body forces and point forces
//--------------------------------------------------------------------------
// [AMPLE] eqs 27-28. See detExtForce.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "detExtForce.h"
#include "constitutive/exercise.h"

namespace ample {

Eigen::VectorXd detExtForce(int nDoF, double g, const std::vector<MaterialPoint>& mpData) {
  // BEGIN EXERCISE detExtForce
  Eigen::VectorXd fext = Eigen::VectorXd::Zero(nDoF);
  for (const MaterialPoint& mp : mpData) {
    const Vector2d fp = mp.mpM * Vector2d(0.0, -g) + mp.fp;  // body (eq 27) + point (eq 28)
    for (int v = 0; v < mp.nn; ++v)
      for (int i = 0; i < nD; ++i) fext(dof(mp.nIN[v], i)) += mp.Svp[v] * fp(i);
  }
  return fext;
  // END EXERCISE
}

Eigen::VectorXd detBodyForce(int nDoF, const std::function<Vector2d(const Vector2d&, double)>& b,
                             double lf, const std::vector<MaterialPoint>& mpData) {
  std::vector<MaterialPoint> loaded = mpData;  // the same points, carrying b V0 as their force
  for (MaterialPoint& mp : loaded) {
    mp.fp = b(mp.X0, lf) * mp.vp0;              // nominal body force times original volume
    mp.mpM = 0.0;                               // no gravity: detExtForce with g = 0 adds fp only
  }
  return detExtForce(nDoF, 0.0, loaded);
}

}  // namespace ample
