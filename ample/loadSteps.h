//--------------------------------------------------------------------------
// loadSteps — the load steps of a run, and the remedy that halves a failed one
//--------------------------------------------------------------------------
// Seed 002 sec 3.2: the load is applied in lstps equal steps; step lstp runs
// from the load factor (lstp-1)/lstps to lstp/lstps. With substeps = 0 (the
// paper's algorithm, the default) next() hands out exactly these steps and
// subdivide() rethrows the failure, which stops the run.
// Remedy (substeps > 0): a step whose Newton-Raphson loop failed is restored
// to the converged state (restoreConverged) and replaced by its two halves,
// each of which may be halved again, up to substeps times.
// Inputs:  lstps · substeps | the failed increment and its error · mpData
// Outputs: increments (lstp, load factors lf0 -> lf1, first/last part of the step)
// Tests:   tests/test_robustness.cpp (large load steps)
//--------------------------------------------------------------------------
#pragma once
#include "errors.h"
#include "mpData.h"
#include <vector>

namespace ample {

struct Increment {
  int lstp = 0;                 // the load step it belongs to
  double lf0 = 0, lf1 = 0;      // load factor at its start and end
  int depth = 0;                // halvings so far (0: the whole step)
  bool first = true;            // the first attempt at its load step (not a half)
  bool last = true;             // it ends its load step
  // scale of the prescribed displacement increments (1 for a whole step)
  double bcScale(int lstps) const { return (lf1 - lf0) * lstps; }
};

class LoadSteps {
 public:
  LoadSteps(int lstps, int substeps);
  bool next(Increment& inc);    // the next increment to solve; false after the last
  // remedy: restore the converged state and queue the two halves of inc, or,
  // when inc may not be halved again (depth = substeps), rethrow e
  void subdivide(const Increment& inc, const RunError& e, std::vector<MaterialPoint>& mpData,
                 bool quiet);

 private:
  int lstps_, substeps_, lstp_ = 0;
  std::vector<Increment> todo_;  // halves still to solve, the next one at the back
};

// undo the point loop's trial state (F, epsE, sig) back to the converged one
void restoreConverged(std::vector<MaterialPoint>& mpData);

}  // namespace ample
