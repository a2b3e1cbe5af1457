//--------------------------------------------------------------------------
// ample — the analysis: load steps, Newton-Raphson iterations, material points
//--------------------------------------------------------------------------
// [AMPLE] sec 4, figs 4-5. ample builds the problem with the setup's
// setupGrid, runs the loops (solve) and writes the output (see
// plotting/writeOutput.h). solve is the loops alone, on an analysis already
// set up, in memory: the tests call it.
// Inputs:  setup (from the table) · P (its parameters) · opt (output folder,
//          VTK interval and format, quiet) | an · log
// Outputs: files in opt.outDir · return value: 0 converged, 1 a load step did
//          not converge or the run could not go on (message on stderr) |
//          an (mesh, mpData, frct) · log; solve throws RunError (NewtonFailure
//          for a failed Newton-Raphson loop) where ample stops the run
// Tests:   tests/test_ample.cpp, tests/test_robustness.cpp
//--------------------------------------------------------------------------
#pragma once
#include "analysis.h"
#include "detMPs.h"
#include "elemMPinfo.h"
#include "plotting/makeVtkWriter.h"
#include "plotting/runLog.h"
#include "setups/setups.h"
#include <string>

namespace ample {

struct RunOptions {
  std::string outDir;      // output folder
  int vtkEvery = 1;        // write mpData_<lstp>.vtk every vtkEvery steps (0 = none)
  bool quiet = false;      // no progress on stdout
  int lastStep = 0;        // stop after this load step (0: all lstps; the tests use it)
  VtkFormat vtkFormat = VtkFormat::Ascii;  // the VTK files as ASCII or BINARY (--vtk-format)
  bool vtkGridEvery = false;  // mesh_<lstp>.vtk with every mpData file, also on a grid that
                              // does not move (--vtk-grid every; postPro.h)
  bool acceptFloor = false;  // accept a step whose residual stalled at its round-off floor
                             // (--accept-floor; checkConverged, ample/solver/roundOffFloor.h)
  // the loops over points: the core's, or the program's choice for large runs
  // (ample/fast/: elemMPinfoFast, detMPsFast; the same numbers, faster)
  BasisLoop basisLoop = elemMPinfo;
  PointLoop pointLoop = detMPs;
};

int ample(const Setup& setup, const Params& P, const RunOptions& opt);

// the load steps lstp = 1..an.lstps with their Newton-Raphson loops ([AMPLE]
// fig 4 below setupGrid); by default quiet and without files
void solve(Analysis& an, RunLog& log, const RunOptions& opt = RunOptions{"", 0, true, 0});

}  // namespace ample
