//--------------------------------------------------------------------------
// loadSteps — the load steps of a run, and the remedy that halves a failed one
//--------------------------------------------------------------------------
// Seed 002 sec 3.2. See loadSteps.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "loadSteps.h"
#include "constitutive/Hooke3d.h"
#include <cstdio>

namespace ample {

LoadSteps::LoadSteps(int lstps, int substeps) : lstps_(lstps), substeps_(substeps) {}

bool LoadSteps::next(Increment& inc) {
  if (!todo_.empty()) {
    inc = todo_.back();
    todo_.pop_back();
    return true;
  }
  if (lstp_ == lstps_) return false;
  ++lstp_;
  inc = Increment{lstp_, double(lstp_ - 1) / lstps_, double(lstp_) / lstps_, 0, true, true};
  return true;
}

void LoadSteps::subdivide(const Increment& inc, const RunError& e,
                          std::vector<MaterialPoint>& mpData, bool quiet) {
  if (inc.depth >= substeps_) throw NewtonFailure(e.what());  // the paper's way: the run stops
  restoreConverged(mpData);
  if (!quiet) std::printf("  %s: retrying with half the increment\n", e.what());
  const double mid = 0.5 * (inc.lf0 + inc.lf1);
  todo_.push_back({inc.lstp, mid, inc.lf1, inc.depth + 1, false, inc.last});  // second half
  todo_.push_back({inc.lstp, inc.lf0, mid, inc.depth + 1, false, false});     // first half
}

void restoreConverged(std::vector<MaterialPoint>& mpData) {
  for (MaterialPoint& mp : mpData) {
    mp.F = mp.Fn;
    mp.epsE = mp.epsEn;
    mp.sig = Hooke3d(mp.epsEn, mp.mCst).Ksig / mp.Fn.determinant();  // stored state is elastic
  }
}

}  // namespace ample
