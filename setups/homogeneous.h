//--------------------------------------------------------------------------
// homogeneous — one material point driven through a homogeneous deformation
//--------------------------------------------------------------------------
// The reference solutions of the shear and stretch setups: the same
// constitutive update as detMPs ([AMPLE] eqs 7-10, Hooke3d or VMconst) on a
// single state, step by step: b_e,tr = dF exp(2 eps_e,n) dF', eps_e,tr =
// ln(b_e,tr)/2, then the model.
// Inputs:  dF (3x3) increment · epsE (6) elastic strain, updated in place ·
//          mCst · cmType
// Outputs: Kirchhoff stress tau (6)
// Tests:   tests/test_ample.cpp (against closed forms written in the test)
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"

namespace ample {

Vector6d homogeneousStep(const Matrix3d& dF, Vector6d& epsE, const MaterialConstants& mCst, CmType cm);

}  // namespace ample
