//--------------------------------------------------------------------------
// Hooke3d — isotropic linear elasticity in Hencky strain / Kirchhoff stress
//--------------------------------------------------------------------------
// [AMPLE] eq 5: tau = D eps_e, with D the 6x6 isotropic stiffness acting on
// engineering shear strains. With logarithmic strain and Kirchhoff stress
// this is hyperelastic for any deformation ([AMPLE] sec 2.1).
// Inputs:  epsEtr (6) trial elastic log strain · mCst: E, nu (rhoY unused)
// Outputs: D (6x6) · Ksig (6) Kirchhoff stress · epsE (6) = epsEtr
// Tests:   tests/test_constitutive.cpp
//--------------------------------------------------------------------------
#pragma once
#include <Eigen/Dense>

namespace ample {

// constitutive/ stands alone (Eigen only): strains, stresses and constants in,
// stresses and tangents out; it knows nothing of material points or grids.
// The same aliases are declared in ample/mpData.h (an alias may be repeated).
using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Eigen::Vector3d;

struct ConstOut {
  Matrix6d D;       // algorithmic tangent d(tau)/d(eps_tr)
  Vector6d Ksig;    // Kirchhoff stress
  Vector6d epsE;    // updated elastic log strain
};

// the material constants a point carries (mpData.h: mCst), set from the setup's E, nu, rhoY
struct MaterialConstants {
  double E = 0;     // Young's modulus (Pa)
  double nu = 0;    // Poisson's ratio
  double rhoY = 0;  // von Mises strength rho_y = sqrt(2 J2) at yield (Pa; VMconst only)
};

Matrix6d elasticStiffness(double E, double nu);  // the 6x6 matrix D of eq 5
ConstOut Hooke3d(const Vector6d& epsEtr, const MaterialConstants& mCst);

}  // namespace ample
