//--------------------------------------------------------------------------
// writeOutput — the run's tables and summary
//--------------------------------------------------------------------------
// prepareOutput creates the output folder and removes the files an earlier
// run left there (so no stale step file looks like part of this run); a folder
// that cannot be made or written in is bad input (InputError naming --out).
// writeOutput writes, each to a temporary name then renamed:
//   steps.csv      lstp, load_factor, NRit, fErr, converged, seconds
//   residuals.csv  lstp, NRit, fErr (every Newton-Raphson pass)
//                  (every field a number: a residual that is not finite is an empty field)
//   mp_final.csv   X0, Y0, x, y, V0, V, sxx, syy, szz, sxy, syz, szx, lpx, lpy
//                  (one row per point, state of the last converged step)
//   history.csv    the setup's per-step figures, if it records any (afterStep;
//                  one that is not finite: an empty field)
//   summary.json   setup, parameters, sizes, iterations, convergence, wall
//                  seconds in total and per function, the setup's results
// Inputs:  setup · P · an (final state) · log · outDir · quiet
// Outputs: files in outDir; the setup's results printed unless quiet
// Tests:   tests/test_output.cpp
//--------------------------------------------------------------------------
#pragma once
#include "runLog.h"
#include "setups/setups.h"
#include <string>

namespace ample {

void prepareOutput(const std::string& outDir);
void writeOutput(const Setup& setup, const Params& P, const Analysis& an, const RunLog& log,
                 const std::string& outDir, bool quiet);

}  // namespace ample
