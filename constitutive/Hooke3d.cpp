//--------------------------------------------------------------------------
// Hooke3d — isotropic linear elasticity in Hencky strain / Kirchhoff stress
//--------------------------------------------------------------------------
// [AMPLE] eq 5. See Hooke3d.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "Hooke3d.h"
#include "exercise.h"

namespace ample {

Matrix6d elasticStiffness(double E, double nu) {
  // BEGIN EXERCISE Hooke3d
  const double c = E / ((1.0 + nu) * (1.0 - 2.0 * nu));
  Matrix6d D = Matrix6d::Zero();
  D.topLeftCorner<3, 3>().setConstant(c * nu);
  for (int i = 0; i < 3; ++i) {
    D(i, i) = c * (1.0 - nu);
    D(i + 3, i + 3) = E / (2.0 * (1.0 + nu));  // shear modulus G on engineering shear
  }
  return D;
  // END EXERCISE
}

ConstOut Hooke3d(const Vector6d& epsEtr, const MaterialConstants& mCst) {
  // BEGIN EXERCISE Hooke3d
  ConstOut out;
  out.D = elasticStiffness(mCst.E, mCst.nu);
  out.Ksig = out.D * epsEtr;
  out.epsE = epsEtr;
  return out;
  // END EXERCISE
}

}  // namespace ample
