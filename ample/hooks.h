//--------------------------------------------------------------------------
// hooks — where the extensions join the main loop, one per phase
//--------------------------------------------------------------------------
// A plain run's hooks are the core functions and empty hooks (the defaults
// below), and solve() is then [AMPLE] fig 4. The program derives its own
// (RunHooks, setups/program/run.cpp) with what the setup and its parameters
// ask for: the fast loops of large runs, the other solvers, the remedies, the
// implicit boundaries, the finite element mode, progress, the log and its timers.
// Each hook is a virtual function, so that gdb's `step` at its call enters it
// (and from there the core function it calls) directly.
// Inputs/outputs: see each hook.
//--------------------------------------------------------------------------
#pragma once
#include "analysis.h"
#include "detFDoFs.h"
#include "detMPs.h"
#include "elemMPinfo.h"
#include "errors.h"
#include "linSolve.h"
#include "updateMPs.h"
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

// the hooks of a plain run: fig 4's functions, and nothing added (linSolve's solveFree and
// updateMPs' updateDomain come from FreeSolve and UpdateDomain, linSolve.h and updateMPs.h)
struct Hooks : FreeSolve, UpdateDomain {
  virtual bool program() const { return false; }  // the program's hooks, which every extension needs
  // solve(): the load steps
  virtual void startStep(Analysis&, const Increment&) const {}              // progress, setup's beforeStep
  virtual void failedStep(Analysis&, const Increment&, const RunError&) const { throw; }  // retries (here
                                                    // none: the run stops); solves the step or throws
  virtual void endStep(Analysis&, const Increment&) const {}                // setup's afterStep, postPro, log
  // loadStep(): the functions of fig 4, each kept or replaced as a whole
  virtual void elemMPinfo(Mesh& mesh, std::vector<MaterialPoint>& mpData, bool /*keepCells: FE mode*/) const {
    ample::elemMPinfo(mesh, mpData);
  }
  virtual void stepTerms(Analysis&, const Increment&, Eigen::VectorXd& /*fext*/) const {}  // body force,
                                                    // geostatic weight, ghost penalty, boundaries
  virtual std::vector<int> detFDoFs(const Mesh& mesh, const std::vector<MaterialPoint>& mpData) const {
    return ample::detFDoFs(mesh, mpData);
  }
  virtual void detMPs(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData, Formulation form,
                      DetMPsOut& mps) const {
    ample::detMPs(uvw, mpData, form, mps);
  }
  virtual void passTerms(const Eigen::VectorXd& /*uvw*/, DetMPsOut& /*mps*/, Eigen::VectorXd& /*fbnd*/) const {}
                                                    // Kt, fint and reactions fbnd of ghost penalty, boundaries
  virtual void afterPass(const Analysis&, const Increment&, int /*NRit*/, double /*fErr*/) const {}  // log;
                                                    // a NaN stops the step
  virtual void checkConverged(const Analysis& an, const Increment& inc, int NRit, double fErr,
                              const Eigen::VectorXd& uvw, const Eigen::VectorXd& load) const {
    ample::checkConverged(an, inc, NRit, fErr, uvw, load);                  // or a diagnosis
  }
  virtual void afterUpdate(Analysis&, const Increment&, int /*NRit*/, double /*fErr*/) const {}  // FE mode,
                                                    // boundaries, split, log
};

}  // namespace ample
