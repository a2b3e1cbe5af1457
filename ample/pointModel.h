//--------------------------------------------------------------------------
// pointModel — a material point's constitutive model, by its cmType
//--------------------------------------------------------------------------
// [AMPLE] eqs 5, 11: Hooke3d (cmType 1, elastic) or VMconst (cmType 2, von Mises
// perfect plasticity) of the trial elastic strain. The loops beside the core's
// (formulations/, locking/, fast/) call it; the core's detMPs writes the same
// choice on its own line, so that gdb's step goes straight into the model.
// Input: the trial elastic strain (Voigt, engineering shear), the point.
// Output: ConstOut (Kirchhoff stress, elastic strain, tangent D).
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"
#include "constitutive/Hooke3d.h"
#include "constitutive/VMconst.h"

namespace ample {

inline ConstOut pointModel(const Vector6d& epsEtr, const MaterialPoint& mp) {
  return mp.cmType == CmType::Elastic ? Hooke3d(epsEtr, mp.mCst) : VMconst(epsEtr, mp.mCst);
}

}  // namespace ample
