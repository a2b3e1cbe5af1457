//--------------------------------------------------------------------------
// elemMPinfoFast — elemMPinfo for large runs: the same result, on threads
//--------------------------------------------------------------------------
// Replaces the run's elemMPinfo as a whole where the program chooses it
// (RunOptions::basisLoop; runs of fewer than fastFrom points: the serial loop the
// program would choose, the core's elemMPinfo, elemMPinfoMesh or elemMPinfoCPDI):
// the points shared out over the threads of pointShares.h, each as that loop takes
// it (pointInfo, meshPointInfo, cpdiPointInfo), the active cells serial. Each
// point's result is its own, so the threads change nothing; an error is the first
// point's in point order, as serially.
// Inputs/outputs: those of elemMPinfo (keepCells: the finite element mode's).
// Tests:   tests/test_pointShares.cpp (against the serial loops, bit for bit)
//--------------------------------------------------------------------------
#pragma once
#include "ample/elemMPinfo.h"
#include "fastFrom.h"

namespace ample {

void elemMPinfoFast(Mesh& mesh, std::vector<MaterialPoint>& mpData, bool keepCells = false);

}  // namespace ample
