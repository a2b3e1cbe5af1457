//--------------------------------------------------------------------------
// ample — the analysis: load steps, Newton-Raphson iterations, material points
//--------------------------------------------------------------------------
// Seed 002 sec 4, figs 4-5. Builds the problem with the setup's setupGrid,
// runs the load steps and writes the output (see plotting/writeOutput.h).
// Inputs:  setup (from the table) · P (its parameters) · opt (output folder,
//          VTK interval, quiet)
// Outputs: files in opt.outDir · return value: 0 converged, 1 a load step did
//          not converge or the run could not go on (message on stderr)
// Tests:   tests/test_ample.cpp
//--------------------------------------------------------------------------
#pragma once
#include "mpData.h"
#include "plotting/runLog.h"
#include "setups/setups.h"
#include <string>

namespace ample {

struct RunOptions {
  std::string outDir;      // output folder
  int vtkEvery = 1;        // write mpData_<lstp>.vtk every vtkEvery steps (0 = none)
  bool quiet = false;      // no progress on stdout
};

int ample(const Setup& setup, const Params& P, const RunOptions& opt);

// the Newton-Raphson loop of one load step (seed 002 fig 5, lines 21-30) to the
// load factor lf, with the prescribed increments scaled by bcScale (1 for a whole
// step); returns uvw, the converged displacement increment; throws NewtonFailure
Eigen::VectorXd solveLoadStep(Analysis& an, int lstp, double lf, double bcScale, RunLog& log,
                              bool quiet);

// one load step: the setup's beforeStep, solveLoadStep, updateMPs, the setup's afterStep
void loadStep(Analysis& an, int lstp, RunLog& log, bool quiet);

// undo the point loop's trial state (F, epsE, sig) back to the converged one
void restoreConverged(std::vector<MaterialPoint>& mpData);

}  // namespace ample
