//--------------------------------------------------------------------------
// stiffnessPattern — the sparsity of Kt for one load step
//--------------------------------------------------------------------------
// Seed 002 eq 30: Kt couples two nodes when a material point links both. The
// points link the same nodes in every Newton-Raphson pass of a load step, so
// the pattern is built once per step (Sigmund and Andreassen's "pattern once")
// and detMPs only refills its values. Built from node buckets: each node
// column collects the nodes of its points, sorted and made unique.
// Inputs:  nDoF · mpData (nIN, nn)
// Outputs: Kt (nDoF x nDoF), compressed, every value 0
// Tests:   tests/test_detMPs.cpp (through detMPs)
//--------------------------------------------------------------------------
#pragma once
#include "linSolve.h"
#include "mpData.h"

namespace ample {

SpMat stiffnessPattern(int nDoF, const std::vector<MaterialPoint>& mpData);

}  // namespace ample
