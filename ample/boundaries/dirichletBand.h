//--------------------------------------------------------------------------
// dirichletBand — the Dirichlet function d(phi) of eq 16 and its band integrals
//--------------------------------------------------------------------------
// [Boundaries] eq 16, with phi the signed distance (positive in the solid):
//   d = 0                     phi < 0        (outside the solid)
//   d = 1 - (1 - phi/delta)^2 0 <= phi <= delta  (the band: a quadratic ramp)
//   d = 1                     phi > delta    (inside the solid)
// so d = 0 on the boundary and rises to 1 at delta into the solid, with slope
//   d' = dd/dphi = (2/delta)(1 - phi/delta) in the band (2/delta at phi = 0,
// 0 at phi = delta: d is C1 at delta, C0 at 0), 0 outside it. For a straight
// boundary grad phi = n, the inward unit normal, so grad d = d' n.
// bandIntegrals: the inner integrals over n in [0, delta] of eqs 21-22 / 26-27,
// whose integrands are products of d (entries of [D1bar]) or 1 (a free
// direction of a roller) with d' (entries of [D2bar]); exact, in closed form
// (the paper's 3-point Gauss rule gives the same: the integrands are
// polynomials of degree <= 4 in phi).
// Inputs:  phi (m) · delta (m, > 0) · n (inward unit normal)
// Outputs: d (-) · d' (1/m) · grad d (1/m) · BandIntegrals
// Tests:   tests/test_boundary.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"

namespace ample {

double dirichletD(double phi, double delta);       // d, eq 16
double dirichletDPrime(double phi, double delta);  // dd/dphi
Vector2d dirichletGrad(double phi, double delta, const Vector2d& n);  // grad d = d' n

struct BandIntegrals {     // integrals over phi in [0, delta]
  double dp;               // int d' dphi    = 1        eq 26: [D1bar] entry 1 (free) x [D2bar]
  double d_dp;             // int d d' dphi  = 1/2      eq 26: [D1bar] entry d x [D2bar]
  double dp_dp;            // int d'^2 dphi  = 4/(3 delta)  eq 27: [D2bar]^T ... [D2bar]
  double d;                // int d dphi     = 2 delta/3    band part of K1 (eq 18, first term)
  double d_d;              // int d^2 dphi   = 8 delta/15   band part of K1 (eq 18, first term)
};
BandIntegrals bandIntegrals(double delta);

}  // namespace ample
