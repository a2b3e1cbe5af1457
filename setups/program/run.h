//--------------------------------------------------------------------------
// run — one run of a setup: setupGrid, the hooks it needs, solve, the output
//--------------------------------------------------------------------------
// ample() sets the setup's analysis up, checks it, runs solve() with the
// hooks its parameters ask for (runHooks) and writes the output (plotting/
// writeOutput.h), also when a load step fails. solveRun is solve() with those
// hooks, in memory: the tests call it.
// Inputs:  setup (from the table) · P (its parameters) · opt (output folder,
//          VTK interval and format, quiet, the fast loops, the stream) | an · log
// Outputs: files in opt.outDir · return value: 0 converged, 1 a load step did
//          not converge or the run could not go on (message on stderr) |
//          an (mesh, mpData, frct) · log; solveRun throws RunError
//          (NewtonFailure for a failed Newton-Raphson loop) where ample stops
// Tests:   tests/test_ample.cpp, tests/test_robustness.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/ample.h"
#include "ample/fast/detMPsFast.h"
#include "ample/fast/elemMPinfoFast.h"
#include "plotting/makeVtkWriter.h"
#include "runLog.h"
#include "setups/setups.h"
#include <functional>
#include <string>

namespace ample {

// what a run hands on as it goes, besides its files: the page's stream (setups/program/wasm/,
// plotting/viewer/) reads the state in memory; empty (the program's default): nothing is called
struct RunStream {
  std::function<void(const Analysis&)> start;                     // the set-up state, before step 1
  std::function<void(int lstp, int NRit, double fErr)> pass;      // after each Newton-Raphson pass
  std::function<void(const Analysis&, const RunLog&, int lstp)> step;  // after each converged step,
                                                                  // its files written
};

struct RunOptions {
  std::string outDir;      // output folder
  int vtkEvery = 1;        // write mpData_<lstp>.vtk every vtkEvery steps (0 = none)
  bool quiet = false;      // no progress on stdout
  int lastStep = 0;        // stop after this load step (0: all lstps; the tests use it)
  VtkFormat vtkFormat = VtkFormat::Ascii;  // the VTK files as ASCII or BINARY (--vtk-format)
  bool vtkGridEvery = false;  // mesh_<lstp>.vtk with every mpData file, also on a grid that
                              // does not move (--vtk-grid every; postPro.h)
  bool acceptFloor = false;  // accept a step whose residual stalled at its round-off floor
                             // (--accept-floor; ample/solver/roundOffFloor.h)
  // the loops over points of a run of fastFrom() points or more in an optimised build
  // (ample/fast/: the same equations, faster); a Debug build, to step through, runs the
  // core's elemMPinfo and the formulation's point loop at every size (pointLoopOf: detMPs
  // for UL; ample/formulations/)
  BasisLoop basisLoop = elemMPinfoFast;
  PointLoop pointLoop = detMPsFast;
  RunStream stream{};      // the state handed on as the run goes (none by default)
};

int ample(const Setup& setup, const Params& P, const RunOptions& opt);

// solve() with the hooks the analysis asks for; by default quiet and without files
void solveRun(Analysis& an, RunLog& log, const RunOptions& opt = RunOptions{"", 0, true, 0});

}  // namespace ample
