//--------------------------------------------------------------------------
// ample — the analysis: load steps, Newton-Raphson iterations, material points
//--------------------------------------------------------------------------
// [AMPLE] sec 4, fig 4 below setupGrid: solve runs the load steps on an
// analysis already set up (mesh, mpData), loadStep one of them. The program
// (setups/program/run.h) sets the analysis up, fills in the hooks and writes
// the output.
// Inputs:  an (mesh, mpData, lstps, tol, NRitMax, g, formulation) · hooks
// Outputs: an (mesh, mpData; frct, uvw of the last step) · a failed load step
//          throws RunError (NewtonFailure: fErr > tol after NRitMax passes)
// Tests:   tests/test_ample.cpp
//--------------------------------------------------------------------------
#pragma once
#include "analysis.h"
#include "hooks.h"

namespace ample {

void solve(Analysis& an, const Hooks& hooks = Hooks());
void loadStep(Analysis& an, const Increment& inc, const Hooks& hooks);

}  // namespace ample
