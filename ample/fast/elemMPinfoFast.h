//--------------------------------------------------------------------------
// elemMPinfoFast — elemMPinfo for large runs: the same result, on threads
//--------------------------------------------------------------------------
// Replaces elemMPinfo (ample/elemMPinfo.h) as a whole where the program chooses
// it (RunOptions::basisLoop; runs of fewer than fastFrom points: elemMPinfo): the
// points (pointCells, pointBasis) shared out over the threads of pointShares.h,
// the active cells serial. Each point's result
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
