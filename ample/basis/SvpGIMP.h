//--------------------------------------------------------------------------
// SvpGIMP — one-dimensional GIMP basis function and its gradient
//--------------------------------------------------------------------------
// [AMPLE] eqs 25-26, the five regions A-E of fig 2 (d = X~p - X~v, l = lp):
//   A  -h-l < d <= -h+l : S = (h+l+d)^2/(4hl)          dS = (h+l+d)/(2hl)
//   B  -h+l < d <= -l   : S = 1 + d/h                  dS = 1/h
//   C    -l < d <= l    : S = 1 - (d^2+l^2)/(2hl)      dS = -d/(hl)
//   D     l < d <= h-l  : S = 1 - d/h                  dS = -1/h
//   E   h-l < d <= h+l  : S = (h+l-d)^2/(4hl)          dS = -(h+l-d)/(2hl)
// tested in this order, 0 elsewhere. Valid for 0 < lp <= h/2 (the domain no
// wider than a cell); for lp = 0 it is the standard MPM function (SvpMPM).
// Inputs:  d · h (grid spacing) · lp (domain half length)
// Outputs: {S, dS}
// Tests:   tests/test_basis.cpp
//--------------------------------------------------------------------------
#pragma once
#include "SvpMPM.h"

namespace ample {

Basis1D SvpGIMP(double d, double h, double lp);

}  // namespace ample
