//--------------------------------------------------------------------------
// runLog — what a run records: per-step and per-iteration rows, timings
//--------------------------------------------------------------------------
// Filled by the main loop (ample/ample.cpp), written by writeOutput as
// steps.csv, residuals.csv and summary.json; the rows of each completed load
// step are also appended as the run goes (appendStepFiles, writeOutput.h). Progress lines on stdout follow
// the original code: one per load step and one per Newton-Raphson iteration.
// What the run has to say on stderr besides a stop is kept in notes and
// printed at its end, after the reason of a stop (the first stderr line).
//--------------------------------------------------------------------------
#pragma once
#include <chrono>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace ample {

struct StepRow {
  int lstp;
  double loadFactor;
  int NRit;          // Newton-Raphson passes taken
  double fErr;       // final normalised residual (eq 35)
  bool converged;
  double seconds;    // wall time of the step
  int negativePivots = -1;  // solver=MUMPS: of the step's last LDL^T (-1: none)
};

struct ResidualRow {
  int lstp;
  int NRit;          // number of linear solves before this residual (0 = first pass)
  double fErr;
};

struct Timers {      // wall seconds spent in each function
  double elemMPinfo = 0, detExtForce = 0, detFDoFs = 0, linSolve = 0, detMPs = 0,
         updateMPs = 0, postPro = 0, total = 0;
};

class Stopwatch {    // lap() returns the seconds since the previous lap (or start)
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return s;
  }
 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// timed(seconds, f, args...) is f(args...) with its wall time added to seconds:
// the main loop times each call of fig 4 without a line of its own
struct ScopedTimer {
  double& seconds;
  Stopwatch sw;
  ~ScopedTimer() { seconds += sw.lap(); }
};
template <class F, class... Args>
decltype(auto) timed(double& seconds, F&& f, Args&&... args) {
  ScopedTimer timer{seconds, Stopwatch()};
  return f(std::forward<Args>(args)...);
}

// how much of the log is already in the step files (writeOutput.h: appendStepFiles)
struct StepFiles {
  bool on = false;              // startStepFiles was called: append at the end of each step
  bool pivots = false;          // steps.csv has the negative_pivots column (solver=MUMPS, PETSC)
  size_t steps = 0, residuals = 0, history = 0;   // rows written so far
};

struct RunLog {
  std::vector<StepRow> steps;
  std::vector<ResidualRow> residuals;
  Timers t;
  int totalNRit = 0;
  int solverAnalyses = 0;       // symbolic analyses of Kt(fd,fd) (a new pattern or fd)
  int luFallbacks = 0;          // passes a symmetric solver= handed to SparseLU
  int splits = 0;               // GIMP points cut in two by the split= remedy (splitPoints)
  long factorisations = 0;      // numeric factorisations of Kt(fd,fd)
  bool converged = true;
  int lastConverged = 0;        // last load step that converged
  std::string message;          // why the run stopped early (empty when complete)
  std::string notes;            // lines for stderr said after the outcome, so that a stop's reason
                                // is the first line: a loose tol, steps accepted at their floor
                                // (--accept-floor), a solver's LU fallback (ample() prints them)
  Stopwatch stepClock;          // lapped at the start and the end of each load step
  StepFiles stream;             // the rows of completed load steps already written (ample())
};

}  // namespace ample
