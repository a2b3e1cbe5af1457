//--------------------------------------------------------------------------
// homogeneous — one material point driven through a homogeneous deformation
//--------------------------------------------------------------------------
// See homogeneous.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "homogeneous.h"
#include "ample/stiffness/tensorOps.h"
#include "constitutive/Hooke3d.h"
#include "constitutive/VMconst.h"

namespace ample {

Vector6d homogeneousStep(const Matrix3d& dF, Vector6d& epsE, const MaterialConstants& mCst, CmType cm) {
  const Matrix3d bT = dF * symExp(2.0 * strainToTensor(epsE)) * dF.transpose();
  const Vector6d epsTr = tensorToStrain(0.5 * symLog(bT));
  const ConstOut out = (cm == CmType::Elastic) ? Hooke3d(epsTr, mCst) : VMconst(epsTr, mCst);
  epsE = out.epsE;
  return out.Ksig;
}

}  // namespace ample
