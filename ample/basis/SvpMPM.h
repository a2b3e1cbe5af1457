//--------------------------------------------------------------------------
// SvpMPM — one-dimensional standard MPM basis function and its gradient
//--------------------------------------------------------------------------
// [AMPLE] eqs 23-24: with d = X~p - X~v,
//   S = 1 + d/h, dS = 1/h   for -h < d <= 0
//   S = 1 - d/h, dS = -1/h  for  0 < d <= h,   and 0 elsewhere.
// Inputs:  d (point minus node position) · h (grid spacing)
// Outputs: {S, dS}
// Tests:   tests/test_basis.cpp
//--------------------------------------------------------------------------
#pragma once

namespace ample {

struct Basis1D {
  double S;   // basis function value
  double dS;  // derivative with respect to the point position
};

Basis1D SvpMPM(double d, double h);

}  // namespace ample
