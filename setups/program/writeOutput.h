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
// As the run goes: startStepFiles writes the headers of steps.csv and
// residuals.csv before the first step (steps.csv with the negative_pivots column
// when solver= is MUMPS or PETSC); appendStepFiles, at the end of each completed
// load step, appends the rows the log gained since the last call (the step's
// residuals, its steps.csv rows, failed attempts included, and the setup's
// history.csv row, the header with the first) and flushes them, so that a run
// stopped or killed leaves every completed step in the three files. writeOutput
// then writes them whole, as before (the same bytes; a steps.csv of a MUMPS run
// whose steps had no LDL^T loses the empty negative_pivots column there).
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
void startStepFiles(const std::string& outDir, const Analysis& an, RunLog& log);
void appendStepFiles(const std::string& outDir, const Analysis& an, RunLog& log);  // RunError if it cannot
void writeOutput(const Setup& setup, const Params& P, const Analysis& an, const RunLog& log,
                 const std::string& outDir, bool quiet);

}  // namespace ample
