//--------------------------------------------------------------------------
// VMconst — von Mises perfect plasticity: backward-Euler return, algorithmic tangent
//--------------------------------------------------------------------------
// [AMPLE] eq 11. See VMconst.h for the algorithm, inputs and outputs.
//--------------------------------------------------------------------------
#include "VMconst.h"
#include "exercise.h"
#include <cmath>

namespace ample {

ConstOut VMconst(const Vector6d& epsEtr, const MaterialConstants& mCst) {
  // BEGIN EXERCISE VMconst
  const double E = mCst.E, nu = mCst.nu, rhoY = mCst.rhoY;
  ConstOut out = Hooke3d(epsEtr, mCst);                 // elastic predictor
  Vector6d m;
  m << 1, 1, 1, 0, 0, 0;
  const double p = out.Ksig.head<3>().sum() / 3.0;      // mean stress
  const Vector6d s = out.Ksig - p * m;                  // deviatoric trial stress
  const double rho = std::sqrt(s.head<3>().squaredNorm() + 2.0 * s.tail<3>().squaredNorm());
  const double f = rho / rhoY - 1.0;                    // yield function (eq 11)
  if (!(f > 1e-9)) return out;                          // elastic: trial state stands

  const double theta = rhoY / rho;                      // radial return factor
  const double K = E / (3.0 * (1.0 - 2.0 * nu)), G = E / (2.0 * (1.0 + nu));
  out.Ksig = p * m + theta * s;                         // stress back on the surface
  const Vector6d eVol = (epsEtr.head<3>().sum() / 3.0) * m;
  out.epsE = eVol + theta * (epsEtr - eVol);            // elastic strain of that stress

  const Vector6d n = s / rho;                           // unit flow direction
  Matrix6d Idev = Matrix6d::Zero();                     // deviatoric projector (eng. shear)
  Idev.topLeftCorner<3, 3>() = Eigen::Matrix3d::Identity() - Eigen::Matrix3d::Constant(1.0 / 3.0);
  Idev.bottomRightCorner<3, 3>() = 0.5 * Eigen::Matrix3d::Identity();
  out.D = K * m * m.transpose() + 2.0 * G * theta * (Idev - n * n.transpose());
  return out;
  // END EXERCISE
}

}  // namespace ample
