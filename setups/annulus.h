//--------------------------------------------------------------------------
// annulus.h — the manufactured solution of the elastic annulus ([Lagrangian] sec 7.4)
//--------------------------------------------------------------------------
// Eq 44: every circle R of the annulus Ri <= R <= Ro turns by
//   theta(R) = alpha 16 (R - Ri)^2 (R - Ro)^2 / (Ri - Ro)^4,
// x = Q(theta(R)) X. Its body force for Hencky elasticity in the updated
// Lagrangian frame (b = -div_x sigma, derived in plotting/annulus_bodyforce.py,
// stated in docs/annulus.md): with gamma = R theta'(R),
//   f = asinh(gamma/2) / sqrt(1 + gamma^2/4), sigma = 2G f [[-gamma/2, 1], [1, gamma/2]]
// in (e_r, e_phi), b_r = G (f + gamma f') gamma' + 2G gamma f / R,
// b_phi = -2G (f' gamma' + 2 f / R), at the reference position X (J = 1, so
// per unit original and current volume alike).
// Tests:   tests/test_annulus.cpp (b against central differences of sigma
//          built from F by Eigen's matrix logarithm)
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"

namespace ample::annulus {

constexpr double Ri = 0.75, Ro = 1.25;          // radii (m), [Lagrangian] sec 7.4

double theta(double R, double alpha);           // eq 44
Vector2d displacement(const Vector2d& X, double alpha);     // u = Q(theta) X - X
Vector2d bodyForce(const Vector2d& X, double alpha, double G);  // N/m3, G shear modulus

}  // namespace ample::annulus
