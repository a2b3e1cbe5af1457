//--------------------------------------------------------------------------
// loadSteps — the remedies that retry a failed load step, and what to try
//--------------------------------------------------------------------------
// [AMPLE] sec 3.2: the load is applied in lstps equal steps (solve). With
// ghost = 0, substeps = 0 (the paper's algorithm, the default) and no lone-node
// rule to switch on, retryStep throws the failure (as NewtonFailure), which stops the run. Otherwise it restores the converged
// state (restoreConverged) and solves the step again (loadStep):
//   lone = 2 (first):  the same increment with the lone-node rule (hooks.detFDoFs
//                      reads an.loneFrom), on from this load step to the end,
//                      if it leaves a dof of the step's free set out;
//   ghost > 0 (then):  the same increment with the ghost penalty, which stays
//                      on from this load step to the end (an.ghostFrom);
//   substeps > 0 (then): its two halves, each of which may be halved again,
//                      up to substeps times.
// A retry that fails goes to hooks.failedStep again (the program's: it logs
// the attempt and calls retryStep).
// Inputs:  the failed increment and its error · an (lone, loneFrom, ghost, ghostFrom,
//          substeps, mesh, mpData) · hooks
// Outputs: an (the step solved) · or the failure thrown as NewtonFailure
// Tests:   tests/test_robustness.cpp (large load steps)
//--------------------------------------------------------------------------
#pragma once
#include "ample/ample.h"
#include "ample/errors.h"
#include "ample/mpData.h"
#include <string>
#include <vector>

namespace ample {

// retry the failed increment inc (error e) with the remedies, or throw e as NewtonFailure
void retryStep(Analysis& an, const Increment& inc, const RunError& e, const Hooks& hooks, bool quiet);

// what to try after a failure of kind e.kind, e.g. "; try substeps=4 (...) or lstps=80":
// smaller load steps for a step that did not converge or went non-finite, the ghost
// penalty for a singular stiffness, the setup's wider grid (an.widerGrid) for a point
// that left it; "" where the message already names its remedy (NRitMax, tol).
// lstpsMax: the largest lstps the setup allows
std::string whatToTry(const RunError& e, const Analysis& an, int lstpsMax);

// undo the point loop's trial state (F, epsE, sig) back to the converged one
void restoreConverged(std::vector<MaterialPoint>& mpData);

}  // namespace ample
