//--------------------------------------------------------------------------
// elemMPinfoFast — elemMPinfo for large runs: the same result, on threads
//--------------------------------------------------------------------------
// Replaces elemMPinfo (ample/elemMPinfo.h) as a whole where the program chooses
// it (RunOptions::basisLoop; runs of fewer than fastFrom points: elemMPinfo): passes 1 and 3 (pointCells, pointBasis) shared out
// over the threads of pointShares.h, each thread its own points and slices of the
// arena; pass 2 (roomForBasis) and the active cells serial. Each point's result
// is its own, so the threads change nothing; an error is the first point's in
// point order, as serially.
// Inputs/outputs: those of elemMPinfo.
// Tests:   tests/test_pointShares.cpp (against elemMPinfo, bit for bit)
//--------------------------------------------------------------------------
#pragma once
#include "ample/elemMPinfo.h"
#include "fastFrom.h"

namespace ample {

void elemMPinfoFast(Mesh& mesh, std::vector<MaterialPoint>& mpData, bool keepCells = false);

}  // namespace ample
