//--------------------------------------------------------------------------
// splitPoints — split GIMP points whose domains have outgrown their cells
//--------------------------------------------------------------------------
// A remedy, off by default (split = 0: nothing is read or changed). With the
// domain update of [Lagrangian] eq 34 (Uii, [AMPLE] eq 34) a GIMP point's half
// length lp(i) = lp0(i) U_ii grows with the stretch; in a slumping body it can
// pass the cell size h(i), where the point reaches into cells it barely touches
// and elemForMP refuses it (more than 3 x 3 cells). After a converged load step
// (after updateMPs, before postPro) each GIMP point with lp(i) > split h(i) is cut
// along direction i into two points:
//   centres  mpC -+ lp(i)/2 e_i       half lengths  lp(i)/2, lp0(i)/2
//   volumes  vp/2, vp0/2              mass          mpM/2     point force  fp/2
//   origins  X0 -+ lp0(i)/2 e_i       displacement  u = mpC - X0 of each half
//   state    F, Fn, sig, epsE, epsEn, mCst, types: the parent's (uniform in it)
// The first half keeps the parent's index (a setup's tagged points keep theirs),
// the second is appended; a half still longer than split h(i) is cut again.
// Halving is exact in binary, so mass and volume are conserved to round-off of
// the sums (exactly for masses that are powers of two). A half is a copy of the
// whole MaterialPoint: its basis (nIN, Svp, dSvp, eIN) is stale until the next
// elemMPinfo and must not be read before it. Standard (MPM) and CPDI points are
// never split (MPM has no domain; CPDI domains follow F through their corners).
// Inputs:  mesh (regular grid: h) · split (fraction of h; <= 0: off) · mpData · quiet
// Outputs: mpData with the split points, the number of splits (cuts); unless quiet, a
//          progress line when there were any
// Tests:   tests/test_splitPoints.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"
#include <vector>

namespace ample {

int splitPoints(const Mesh& mesh, double split, std::vector<MaterialPoint>& mpData, bool quiet = true);

}  // namespace ample
