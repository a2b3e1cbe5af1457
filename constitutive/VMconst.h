//--------------------------------------------------------------------------
// VMconst — von Mises perfect plasticity: backward-Euler return, algorithmic tangent
//--------------------------------------------------------------------------
// [AMPLE] eq 11: f = rho/rho_y - 1, rho = sqrt(2 J2) = |s|. Elastic
// predictor (eq 5); if f > 0 the associated backward-Euler corrector returns
// the deviatoric stress radially, s = (rho_y/rho_tr) s_tr, which is the exact
// solution of the backward-Euler equations for this surface. The consistent
// tangent is D = K m m' + 2G theta (I_dev - n n'), theta = rho_y/rho_tr,
// n = s_tr/|s_tr| (the derivative of this return map).
// Inputs:  epsEtr (6) trial elastic log strain · mCst: E, nu, rhoY
// Outputs: D (6x6) algorithmic tangent · Ksig (6) · epsE (6)
// Tests:   tests/test_constitutive.cpp
//--------------------------------------------------------------------------
#pragma once
#include "Hooke3d.h"

namespace ample {

ConstOut VMconst(const Vector6d& epsEtr, const MaterialConstants& mCst);

}  // namespace ample
