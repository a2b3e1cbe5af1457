//--------------------------------------------------------------------------
// Hooke3d — isotropic linear elasticity in Hencky strain / Kirchhoff stress
//--------------------------------------------------------------------------
// Seed 002 eq 5: tau = D eps_e, with D the 6x6 isotropic stiffness acting on
// engineering shear strains. With logarithmic strain and Kirchhoff stress
// this is hyperelastic for any deformation (seed 002 sec 2.1).
// Inputs:  epsEtr (6) trial elastic log strain · mCst (3) [E, nu, -]
// Outputs: D (6x6) · Ksig (6) Kirchhoff stress · epsE (6) = epsEtr
// Tests:   tests/test_constitutive.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"

namespace ample {

struct ConstOut {
  Matrix6d D;       // algorithmic tangent d(tau)/d(eps_tr)
  Vector6d Ksig;    // Kirchhoff stress
  Vector6d epsE;    // updated elastic log strain
};

Matrix6d elasticStiffness(double E, double nu);  // the 6x6 matrix D of eq 5
ConstOut Hooke3d(const Vector6d& epsEtr, const Vector3d& mCst);

}  // namespace ample
