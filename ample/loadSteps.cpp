//--------------------------------------------------------------------------
// loadSteps — the load steps of a run, and the remedies that retry a failed one
//--------------------------------------------------------------------------
// Seed 002 sec 3.2. See loadSteps.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "loadSteps.h"
#include "constitutive/Hooke3d.h"
#include <algorithm>
#include <cstdio>

namespace ample {

LoadSteps::LoadSteps(int lstps, int substeps, int lastStep)
    : lstps_(lstps), substeps_(substeps), lastStep_(lastStep > 0 ? std::min(lastStep, lstps) : lstps) {}

bool LoadSteps::next(Increment& inc) {
  if (!todo_.empty()) {
    inc = todo_.back();
    todo_.pop_back();
    return true;
  }
  if (lstp_ == lastStep_) return false;
  ++lstp_;
  inc = Increment{lstp_, double(lstp_ - 1) / lstps_, double(lstp_) / lstps_, 0, true, true, ""};
  return true;
}

void LoadSteps::retry(const Increment& inc, const RunError& e, Analysis& an, bool quiet) {
  std::string failure = e.what();
  if (!inc.withoutGhost.empty())                                  // it failed with the penalty too
    failure += " (with the ghost penalty " + std::to_string(an.ghost) + "; without it: " +
               inc.withoutGhost + ")";
  if (an.ghost > 0 && an.ghostFrom == 0) {                        // remedy 1: the ghost penalty
    an.ghostFrom = inc.lstp;                                      // on from here to the end
    restoreConverged(an.mpData);
    if (!quiet) std::printf("  %s: retrying with the ghost penalty\n", e.what());
    Increment again = inc;
    again.first = false;
    again.withoutGhost = e.what();
    todo_.push_back(again);
    return;
  }
  if (inc.depth >= substeps_) throw NewtonFailure(failure);       // the paper's way: the run stops
  restoreConverged(an.mpData);                                    // remedy 2: halves
  if (!quiet) std::printf("  %s: retrying with half the increment\n", failure.c_str());
  const double mid = 0.5 * (inc.lf0 + inc.lf1);
  todo_.push_back({inc.lstp, mid, inc.lf1, inc.depth + 1, false, inc.last, ""});  // second half
  todo_.push_back({inc.lstp, inc.lf0, mid, inc.depth + 1, false, false, ""});     // first half
}

void restoreConverged(std::vector<MaterialPoint>& mpData) {
  for (MaterialPoint& mp : mpData) {
    mp.F = mp.Fn;
    mp.epsE = mp.epsEn;
    mp.sig = Hooke3d(mp.epsEn, mp.mCst).Ksig / mp.Fn.determinant();  // stored state is elastic
  }
}

}  // namespace ample
