//--------------------------------------------------------------------------
// loadSteps — the load steps of a run, and the remedies that retry a failed one
//--------------------------------------------------------------------------
// [AMPLE] sec 3.2: the load is applied in lstps equal steps; step lstp runs
// from the load factor (lstp-1)/lstps to lstp/lstps. With substeps = 0 (the
// paper's algorithm, the default) next() hands out exactly these steps and
// retry() rethrows a failure, which stops the run.
// retry() is the one call of both remedies when a step fails; each restores the
// converged state (restoreConverged) and queues the work again:
//   ghost > 0 (first): the same increment with the ghost penalty, which stays
//                      on from this load step to the end (an.ghostFrom);
//   substeps > 0 (then): its two halves, each of which may be halved again,
//                      up to substeps times.
// With both off it rethrows the failure, which stops the run.
// Inputs:  lstps · substeps | the failed increment and its error · an (ghost,
//          ghostFrom, mpData)
// Outputs: increments (lstp, load factors lf0 -> lf1, first/last part of the step)
// Tests:   tests/test_robustness.cpp (large load steps)
//--------------------------------------------------------------------------
#pragma once
#include "ample/analysis.h"
#include "ample/errors.h"
#include "ample/mpData.h"
#include <string>
#include <vector>

namespace ample {

struct Increment {
  int lstp = 0;                 // the load step it belongs to
  double lf0 = 0, lf1 = 0;      // load factor at its start and end
  int depth = 0;                // halvings so far (0: the whole step)
  bool first = true;            // the first attempt at its load step (not a half)
  bool last = true;             // it ends its load step
  std::string withoutGhost;     // the failure without the ghost penalty, if retried with it
  // scale of the prescribed displacement increments (1 for a whole step)
  double bcScale(int lstps) const { return (lf1 - lf0) * lstps; }
};

class LoadSteps {
 public:
  LoadSteps(int lstps, int substeps, int lastStep = 0);  // lastStep 0: all lstps
  bool next(Increment& inc);    // the next increment to solve; false after the last
  // remedies: restore the converged state and queue inc again with the ghost
  // penalty, or its two halves; when neither is allowed, throw e (NewtonFailure)
  void retry(const Increment& inc, const RunError& e, Analysis& an, bool quiet);

 private:
  int lstps_, substeps_, lastStep_, lstp_ = 0;
  std::vector<Increment> todo_;  // halves still to solve, the next one at the back
};

// what to try after a failure of kind e.kind, e.g. "; try substeps=4 (...) or lstps=80":
// smaller load steps for a step that did not converge or went non-finite, the ghost
// penalty for a singular stiffness, the setup's wider grid (an.widerGrid) for a point
// that left it; "" where the message already names its remedy (NRitMax, tol).
// lstpsMax: the largest lstps the setup allows
std::string whatToTry(const RunError& e, const Analysis& an, int lstpsMax);

// undo the point loop's trial state (F, epsE, sig) back to the converged one
void restoreConverged(std::vector<MaterialPoint>& mpData);

}  // namespace ample
