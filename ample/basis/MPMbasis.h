//--------------------------------------------------------------------------
// MPMbasis — two-dimensional basis functions and gradients of one point
//--------------------------------------------------------------------------
// [AMPLE] eq 22 and footnote 3: S(X,Y) = S(X) S(Y),
// dS/dX = dS(X) S(Y), dS/dY = S(X) dS(Y), from SvpMPM (mpType 1, eqs 23-24)
// or SvpGIMP (mpType 2, eqs 25-26) in each direction, on the regular grid.
// CPDI points (cpdiBasis, ample/cpdi/) and general meshes (meshMPMbasis,
// ample/meshes/) have their own.
// Inputs:  coord (nodes x 2) · mp.nIN, mp.nn, mp.mpC, mp.lp, mp.mpType · h (2)
// Outputs: mp.Svp (nn) · mp.dSvp (2 x nn), gradients with respect to X~ (start of step),
//          of its first nn entries (elemMPinfo; by hand: set mp.nn, mp.nIN)
// Tests:   tests/test_basis.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"

namespace ample {

void MPMbasis(const Mesh& mesh, MaterialPoint& mp);

}  // namespace ample
