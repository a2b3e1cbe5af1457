//--------------------------------------------------------------------------
// loadSteps — the load steps of a run, and the remedies that retry a failed one
//--------------------------------------------------------------------------
// [AMPLE] sec 3.2. See loadSteps.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "loadSteps.h"
#include "ample/detFDoFs.h"
#include "constitutive/Hooke3d.h"
#include <algorithm>
#include <cstdio>

namespace ample {

// switch the lone-node rule on from inc's load step (an.loneFrom) if it leaves a dof of
// this step's free set out (the basis of the step start is still in mpData), else leave it off
static bool loneRuleChanges(Analysis& an, const Increment& inc, const Hooks& hooks) {
  const std::vector<int> without = detFDoFs(an.mesh, an.mpData);
  an.loneFrom = inc.lstp;                                         // the hook's free set is now the rule's
  if (hooks.detFDoFs(an.mesh, an.mpData) != without) return true;
  an.loneFrom = 0;
  return false;
}

// one attempt at inc; a failure goes to the hook again (which may retry it in turn)
static void attempt(Analysis& an, const Increment& inc, const Hooks& hooks) {
  try {
    loadStep(an, inc, hooks);
  } catch (const RunError& e) {
    hooks.failedStep(an, inc, e);                                 // (Hooks: rethrows e)
  }
}

void retryStep(Analysis& an, const Increment& inc, const RunError& e, const Hooks& hooks, bool quiet) {
  const std::string failure = e.what() + (inc.earlier.empty() ? "" : " (" + inc.earlier.substr(2) + ")");
  if (an.lone == 2 && an.loneFrom == 0 && loneRuleChanges(an, inc, hooks)) {  // remedy 1: lone nodes
    restoreConverged(an.mpData);                                  // (an.loneFrom: on to the end)
    if (!quiet) std::printf("  %s: retrying with the lone-node rule\n", e.what());
    Increment again = inc;
    again.earlier += "; with the lone-node rule; without it: " + std::string(e.what());
    return attempt(an, again, hooks);
  }
  if (an.ghost > 0 && an.ghostFrom == 0) {                        // remedy 2: the ghost penalty
    an.ghostFrom = inc.lstp;                                      // on from here to the end
    restoreConverged(an.mpData);
    if (!quiet) std::printf("  %s: retrying with the ghost penalty\n", e.what());
    Increment again = inc;
    char gamma[32];
    std::snprintf(gamma, sizeof gamma, "%g", an.ghost);
    again.earlier += "; with the ghost penalty " + std::string(gamma) + "; without it: " + e.what();
    return attempt(an, again, hooks);
  }
  if (inc.depth >= an.substeps) throw NewtonFailure(failure, e.kind);  // the paper's way: the run stops
  restoreConverged(an.mpData);                                    // remedy 3: halves
  if (!quiet) std::printf("  %s: retrying with half the increment\n", failure.c_str());
  const double mid = 0.5 * (inc.lf0 + inc.lf1);
  attempt(an, {inc.lstp, inc.lf0, mid, inc.share / 2, inc.depth + 1, ""}, hooks);  // first half
  attempt(an, {inc.lstp, mid, inc.lf1, inc.share / 2, inc.depth + 1, ""}, hooks);  // second half
}

static std::string smallerSteps(const Analysis& an, int lstpsMax) {
  const std::string lstps = 2 * an.lstps <= lstpsMax ? "lstps=" + std::to_string(2 * an.lstps) : "";
  if (an.substeps >= 30) return lstps.empty() ? "" : "; try " + lstps;
  const std::string sub = "substeps=" + std::to_string(an.substeps ? std::min(30, 2 * an.substeps) : 4) +
                          " (a failed load step is retried in halves)";
  return "; try " + sub + (lstps.empty() ? "" : " or " + lstps);
}

// the split= remedy when a GIMP domain has outgrown half a cell (lp(i) > h(i) / 2), else ""
static std::string splitAdvice(const Analysis& an) {
  if (an.split > 0 || !an.mesh.regular()) return "";
  double r = 0;                                                   // the largest lp(i) / h(i)
  for (const MaterialPoint& mp : an.mpData)
    if (mp.mpType == MpType::GIMP)
      for (int i = 0; i < nD; ++i) r = std::max(r, mp.lp(i) / an.mesh.h(i));
  if (r <= 0.5) return "";
  char buf[200];
  std::snprintf(buf, sizeof buf, "; GIMP domains have grown to lp = %.2f h: try split=0.5 (a point with "
                "lp > h/2 is cut in two after each load step)", r);
  return buf;
}

std::string whatToTry(const RunError& e, const Analysis& an, int lstpsMax) {
  switch (e.kind) {
    case Failure::DomainTooLarge:
      return an.split > 0 ? "; try a smaller split= (cut the domains earlier)" + smallerSteps(an, lstpsMax)
                          : "; try split=0.5 (a GIMP point with lp > h/2 is cut in two after each load step)";
    case Failure::NotConverged:
    case Failure::Stalled:
    case Failure::NotFinite:
      if (an.locking == Locking::Fbar && an.ghost == 0 && splitAdvice(an).empty())
      {
        const std::string steps = smallerSteps(an, lstpsMax);    // "; try ..." or ""
        return "; try ghost=0.01 (with locking=Fbar a node that only the edge of a point's domain reaches "
               "keeps little stiffness: the ghost penalty pins it)" + (steps.empty() ? "" : "; or" + steps.substr(5));
      }
      return splitAdvice(an) + smallerSteps(an, lstpsMax);
    case Failure::Singular: {  // a nearly empty cell, or a load step so large that cells empty
      const std::string halves = an.substeps >= 30 ? std::string("more points per cell (mp)")
          : "substeps=" + std::to_string(an.substeps ? std::min(30, 2 * an.substeps) : 4) +
            " (a failed load step is retried in halves)";
      if (!splitAdvice(an).empty()) return splitAdvice(an) + "; or " + halves;
      if (an.lone == 0)
        return "; try lone=2 (the redundant dofs of nodes that one point alone reaches are left out) or " + halves;
      if (an.mesh.regular() && an.ghost == 0)
        return "; try ghost=0.01 (the ghost penalty pins the nearly free nodes of barely filled cells) or " +
               halves + "; with neither, check the boundary conditions";
      return "; try " + halves + ", or check the boundary conditions";
    }
    case Failure::Inverted:  // a loose tol accepted it, else the step was too large
      return an.tol > 1e-6 ? "; try a smaller tol (the paper's tol=1e-9)" : smallerSteps(an, lstpsMax);
    case Failure::LeftGrid:
      return an.widerGrid.empty() ? "; the setup's grid has no room for this motion" + smallerSteps(an, lstpsMax)
                                  : "; try a wider grid, " + an.widerGrid;
    default: return "";
  }
}

void restoreConverged(std::vector<MaterialPoint>& mpData) {
  for (MaterialPoint& mp : mpData) {
    mp.F = mp.Fn;
    mp.epsE = mp.epsEn;
    mp.sig = Hooke3d(mp.epsEn, mp.mCst).Ksig / mp.Fn.determinant();  // stored state is elastic
  }
}

}  // namespace ample
