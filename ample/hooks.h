//--------------------------------------------------------------------------
// hooks — where the extensions join the main loop, one per phase
//--------------------------------------------------------------------------
// A plain run's hooks are the core functions and empty hooks (the defaults
// below), and solve() is then [AMPLE] fig 4. The program fills them in
// (ample/program/run.cpp) with what the setup and its parameters ask for:
// the fast loops of large runs, the other solvers, the remedies, the implicit
// boundaries, the finite element mode, progress, the log and its timers.
// Inputs/outputs: see each hook; an empty one is skipped.
//--------------------------------------------------------------------------
#pragma once
#include "analysis.h"
#include "detFDoFs.h"
#include "detMPs.h"
#include "elemMPinfo.h"
#include "errors.h"
#include "linSolve.h"
#include "updateMPs.h"
#include <functional>
#include <string>

namespace ample {

struct Increment {              // load step lstp, or a part of it, from load factor lf0 to lf1
  int lstp = 1;
  double lf0 = 0, lf1 = 1;
  double share = 1;             // its share of the step's prescribed increments (1: the whole step)
  int depth = 0;                // halvings so far (0: the whole step; remedy substeps=)
  std::string earlier{};        // how this step failed before a remedy came on (ghost=, lone=), e.g.
                                //   "; with the lone-node rule; without it: ..." ("" none)
};

// the core's convergence check (ample.cpp): fErr > tol, or not a number, throws NewtonFailure
// naming the load step and fErr; uvw and load (fext + frct) are for a hook that explains more
void checkConverged(const Analysis& an, const Increment& inc, int NRit, double fErr,
                    const Eigen::VectorXd& uvw, const Eigen::VectorXd& load);

struct Hooks;

struct Hooks {
  // solve(): the load steps
  std::function<void(Analysis& an, const Increment& inc)> startStep;        // progress, setup's beforeStep
  std::function<void(Analysis& an, const Increment& inc, const RunError& e, const Hooks& hooks)>
      failedStep;                                                            // retries (empty: stop); it
                                                                            // solves the step or throws
  std::function<void(Analysis& an, const Increment& inc)> endStep;          // setup's afterStep, postPro, log
  // loadStep(): the functions of fig 4, each replaced as a whole or kept
  std::function<void(Mesh&, std::vector<MaterialPoint>&, bool keepCells)> elemMPinfo =  // keepCells: FE mode's
      [](Mesh& mesh, std::vector<MaterialPoint>& mpData, bool) { ample::elemMPinfo(mesh, mpData); };
  std::function<void(Analysis& an, const Increment& inc, Eigen::VectorXd& fext)> stepTerms;  // body force,
                                                                            // ghost penalty, boundaries
  std::function<std::vector<int>(const Mesh&, const std::vector<MaterialPoint>&)> detFDoFs = ample::detFDoFs;
  FreeSolve solveFree = ample::solveFree;                                   // linSolve's Kt(fd,fd) \ rhs
  std::function<void(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>&, Formulation, DetMPsOut&)>
      detMPs = PointLoop(ample::detMPs);
  std::function<void(const Eigen::VectorXd& uvw, DetMPsOut& mps, Eigen::VectorXd& fbnd)> passTerms;  // Kt,
                                                     // fint and reactions fbnd of ghost penalty, boundaries
  std::function<void(const Analysis& an, const Increment& inc, int NRit, double fErr)> afterPass;  // log;
                                                                            // a NaN stops the step
  std::function<void(const Analysis& an, const Increment& inc, int NRit, double fErr, const Eigen::VectorXd& uvw,
                     const Eigen::VectorXd& load)> checkConverged = ample::checkConverged;  // or a diagnosis
  UpdateDomain updateDomain = ample::updateGIMPDomain;                      // updateMPs' domains (eq 34)
  std::function<void(Analysis& an, const Increment& inc, int NRit, double fErr)> afterUpdate;  // FE mode,
                                                                            // boundaries, split, log
};

}  // namespace ample
