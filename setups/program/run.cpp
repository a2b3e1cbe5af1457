//--------------------------------------------------------------------------
// run — one run of a setup: setupGrid, the hooks it needs, solve, the output
//--------------------------------------------------------------------------
// RunHooks connects the extensions to solve()'s hooks (ample/hooks.h), each
// only where the analysis asks for it:
//   startStep    progress line, step clock, the setup's beforeStep
//   elemMPinfo   elemMPinfoCPDI with CPDI points (cpdi/), elemMPinfoMesh on a general mesh
//                (meshes/), elemMPinfoFast for large runs (opt.basisLoop; not in a Debug
//                build), timed
//   stepTerms    the weight in full from step 1 (geostatic=on: initial/geostatic.h),
//                the body force (detBodyForce), the ghost penalty of the step
//                (remedies/ghostPenalty.h), the implicit boundaries' K and f
//                (boundaries/ibStiffness.h)
//   detFDoFs     the lone-node rule (remedies/loneNodes.h): lone=1 every step, lone=2
//                (the default) from the first step that fails without it
//   solveFree    linSolve's Kt(fd,fd) \ rhs by the solver= choice with its analysis kept
//                (solver/chosenSolve.h), also for SparseLU on large runs
//   detMPs       detMPsFast for large runs (opt.pointLoop), or detMPsFbar (locking=Fbar;
//                ample/locking/), timed
//   passTerms    the ghost penalty's and the boundaries' Kt, fint and reactions
//   afterPass    progress, residuals.csv, opt.stream.pass; a NaN or Inf stops the step
//   checkConverged  why a step failed (round-off floor, still falling:
//                roundOffFloor.h), --accept-floor; an inverted point stops it
//   updateDomain the other domain updates (domains/updateDomain.h): CPDI points,
//                a domainUpdate= other than Uii
//   afterUpdate  steps.csv, the finite element mode's moveMesh, the boundaries'
//                motion, the split= remedy
//   failedStep   the remedies lone=2, ghost= and substeps= (remedies/loadSteps.h)
//   endStep      the setup's afterStep, postPro, the step's time, its rows of
//                steps.csv, residuals.csv and history.csv appended (writeOutput.h)
// See run.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "run.h"
#include "ample/boundaries/ibStiffness.h"
#include "ample/cpdi/elemMPinfoCPDI.h"
#include "ample/detExtForce.h"
#include "ample/domains/updateDomain.h"
#include "ample/errors.h"
#include "ample/fast/fastFrom.h"
#include "ample/formulations/detMPsForm.h"
#include "ample/initial/geostatic.h"
#include "ample/locking/detMPsFbar.h"
#include "ample/meshes/cellSearch.h"
#include "ample/meshes/elemMPinfoMesh.h"
#include "ample/remedies/ghostPenalty.h"
#include "ample/remedies/loadSteps.h"
#include "ample/remedies/loneNodes.h"
#include "ample/remedies/splitPoints.h"
#include "ample/solver/chosenSolve.h"
#include "ample/solver/roundOffFloor.h"
#include "ample/updateMPs.h"
#include "plotting/postPro.h"
#include "writeOutput.h"
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <new>
#include <sstream>

namespace ample {

// what the hooks keep between their calls in one run
struct RunState {
  FreeSystem Kff;                  // the chosen solver's Kt(fd,fd) and its analysis
  SpMat Kgp;                       // the ghost penalty of this step (empty: none)
  ImplicitBoundaries ib;           // the implicit boundaries' terms of this step
  int NRit = 0;                    // passes of the current attempt, and its last fErr
  double fErr = 1.0;               //   (steps.csv's row of a failed attempt)
  Stopwatch gap;                   // times detExtForce and updateMPs, which have no hook
};
struct LastStepDone {};            // opt.lastStep reached (solveRun stops there)

// helpers of this page (defined below it): bookkeeping, not algorithm
static void checkAnalysis(const Analysis& an);
static std::string looseTolWarning(const Analysis& an);
static int lstpsMax(const Params& P);
static void startStep(Analysis& an, int lstp, RunLog& log, bool quiet);
static SpMat ghostPenaltyOf(const Analysis& an);
static void recordPass(RunLog& log, const std::vector<MaterialPoint>& mpData, int lstp, int NRit,
                       double fErr, bool quiet);
static void explainFailure(const Analysis& an, RunLog& log, int lstp, int NRit, double fErr,
                           const Eigen::VectorXd& uvw, const Eigen::VectorXd& load, bool acceptFloor);
static void recordStep(RunLog& log, const Increment& inc, int NRit, double fErr, FreeSystem& Kff,
                       bool converged);
static void checkNotInverted(const std::vector<MaterialPoint>& mpData, int lstp, double fErr);

// the hooks of this run (the list at the top of the page): each chosen once, in the
// constructor; a hook times its core function with a ScopedTimer (runLog.h) and calls it
struct RunHooks : Hooks {
  Analysis& an;
  RunLog& log;
  Timers& T;
  const RunOptions& opt;
  RunState& x;
  BasisLoop basisLoop = nullptr;                 // the core's elemMPinfo, or CPDI's, a general mesh's,
                                                 // the fast one of large runs
  PointLoop pointLoop = ample::detMPs;           // the core's point loop, or the fast one
  bool chosen = false;                           // solver= (or a large run): the chosen solver
  bool cpdi = false;                             // CPDI points: their domain update

  RunHooks(Analysis& a, RunLog& l, const RunOptions& o, RunState& s) : an(a), log(l), T(l.t), opt(o), x(s) {
#ifndef AMPLE_CORE_LOOPS
    const bool large = an.mpData.size() >= size_t(fastFrom());     // chosen once, for the run
#else
    const bool large = false;      // a Debug build, to step through: the core's loops at every size
#endif
    cpdi = std::any_of(an.mpData.begin(), an.mpData.end(), [](const MaterialPoint& mp) { return isCPDI(mp); });
    if (cpdi) basisLoop = elemMPinfoCPDI;                            // CPDI points (cpdi/), on either mesh
    else if (!an.mesh.regular()) basisLoop = elemMPinfoMesh;         // a general mesh (meshes/)
    if (large && opt.basisLoop) basisLoop = opt.basisLoop;           // each of them, faster
    if (large) pointLoop = opt.pointLoop;                             // the fast loop, every formulation
    else if (an.formulation != Formulation::UL) pointLoop = detMPsForm;  // PC, SS (formulations/)
    x.Kff.choice = an.solver;                                        // SparseLU, or LDLT if symmetric
    chosen = large || an.solver != LinearSolver::LU;
  }
  bool program() const override { return true; }

  void startStep(Analysis& a, const Increment& inc) const override {
    ample::startStep(a, inc.lstp, log, opt.quiet);
  }
  void elemMPinfo(Mesh& mesh, std::vector<MaterialPoint>& mpData, bool keepCells) const override {
    ScopedTimer timer{T.elemMPinfo, Stopwatch()};
    basisLoop ? basisLoop(mesh, mpData, keepCells) : ample::elemMPinfo(mesh, mpData);
    x.gap.lap();                                                     // detExtForce from here
  }
  void stepTerms(Analysis& a, const Increment& inc, Eigen::VectorXd& fext) const override {
    T.detExtForce += x.gap.lap();
    if (a.geostatic) fext += timed(T.detExtForce, selfWeight, int(fext.size()), a.g, a.mpData) * (1.0 - inc.lf1);
    if (a.bodyForce) fext += timed(T.detExtForce, detBodyForce, int(fext.size()), a.bodyForce, inc.lf1, a.mpData);
    x.Kgp = ghostPenaltyOf(a);                                       // remedy (off: empty)
    if (a.boundaries.has_value())                                    // [Boundaries]: K_IB, f_IB
      x.ib = ibStiffness(a.mesh, boundariesOf(a), a.mpData, inc.lstp, inc.share);
    x.NRit = 0, x.fErr = 1.0;
  }
  std::vector<int> detFDoFs(const Mesh& mesh, const std::vector<MaterialPoint>& mpData) const override {
    ScopedTimer timer{T.detFDoFs, Stopwatch()};                      // the lone-node rule (remedy): lone=1, or lone=2 once needed
    return an.lone == 1 || an.loneFrom > 0 ? detFDoFsLone(mesh, mpData, {&x.Kgp, &x.ib.K}) : ample::detFDoFs(mesh, mpData);
  }
  Eigen::VectorXd solveFree(const SpMat& Kt, const std::vector<int>& fd, const Eigen::VectorXd& rhs,
                            int NRit) const override {
    ScopedTimer timer{T.linSolve, Stopwatch()};
    if (!chosen) x.Kff.builds++, x.Kff.factorisations++;             // SparseLU analyses every pass
    return chosen ? chosenSolveFree(x.Kff, Kt, fd, rhs, NRit) : ample::solveFree(Kt, fd, rhs, NRit);
  }
  void detMPs(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData, Formulation form,
              DetMPsOut& mps) const override {
    ScopedTimer timer{T.detMPs, Stopwatch()};                        // anti-locking: F-bar, B-bar
    an.locking == Locking::Fbar ? detMPsFbar(an.mesh, uvw, mpData, form, mps) : pointLoop(uvw, mpData, form, mps);
  }
  void passTerms(const Eigen::VectorXd& uvw, DetMPsOut& mps, Eigen::VectorXd& fbnd) const override {
    if (an.ghost == 0 && !an.boundaries.has_value()) return;
    addGhostPenalty(x.Kgp, uvw, mps.Kt, mps.fint);                   // remedy (off: nothing)
    fbnd = addImplicitBoundaries(x.ib, uvw, mps.Kt, mps.fint);       // [Boundaries] (none: 0)
  }
  void afterPass(const Analysis& a, const Increment& inc, int NRit, double fErr) const override {
    x.NRit = NRit, x.fErr = fErr;
    if (opt.stream.pass) opt.stream.pass(inc.lstp, NRit, fErr);
    recordPass(log, a.mpData, inc.lstp, NRit, fErr, opt.quiet);     // throws on NaN
    x.NRit = NRit + 1;
  }
  void checkConverged(const Analysis& a, const Increment& inc, int NRit, double fErr,
                      const Eigen::VectorXd& uvw, const Eigen::VectorXd& load) const override {
    explainFailure(a, log, inc.lstp, NRit, fErr, uvw, load, opt.acceptFloor);  // fErr > tol: throws
    checkNotInverted(a.mpData, inc.lstp, fErr);                      // det F <= 0 accepted: throws
    recordStep(log, inc, NRit, fErr, x.Kff, true);                   // converged: its steps.csv row
    x.gap.lap();                                                     // updateMPs from here
  }
  void updateDomain(const Mesh& mesh, const Eigen::VectorXd& uvw, MaterialPoint& mp) const override {
    if (cpdi || an.domainUpdate != DomainUpdate::Uii) return ample::updateDomain(mesh, uvw, an.domainUpdate, mp);
    updateGIMPDomain(mesh, uvw, mp);                                 // [Lagrangian]'s, CPDI's domains above
  }
  void afterUpdate(Analysis& a, const Increment& inc, int /*NRit*/, double /*fErr*/) const override {
    T.updateMPs += x.gap.lap();
    if (a.fem) moveMesh(a.mesh, a.uvw);                              // FEM: the mesh follows (MPM: reset)
    if (a.boundaries.has_value()) {                                  // [Boundaries]: forces, motion by du
      a.ibForce = boundaryForces(x.ib, a.uvw, int(boundariesOf(a).size()));
      moveBoundaries(editBoundaries(a), inc.lstp, inc.share);
    }
    if (a.split > 0) log.splits += splitPoints(a.mesh, a.split, a.mpData, opt.quiet);  // remedy
  }
  void failedStep(Analysis& a, const Increment& inc, const RunError& e) const override {
    if (e.kind == Failure::Other || e.kind == Failure::LeftGrid || e.kind == Failure::DomainTooLarge)
      throw;                                                         // not the Newton loop's: stop
    recordStep(log, inc, x.NRit, x.fErr, x.Kff, false);
    retryStep(a, inc, e, *this, opt.quiet);                          // remedies (off: throws e)
  }
  void endStep(Analysis& a, const Increment& inc) const override {
    if (a.afterStep) a.afterStep(a, inc.lstp, inc.lf1);             // setup's hook
    timed(T.postPro, postPro, a.mesh, a.mpData, a.uvw, inc.lstp, opt.vtkEvery, opt.outDir, opt.vtkFormat,
          opt.vtkGridEvery || a.fem || a.gridMoves);
    log.steps.back().seconds = log.stepClock.lap();
    log.lastConverged = inc.lstp;
    appendStepFiles(opt.outDir, a, log);                             // the step's rows, flushed (ample())
    if (opt.stream.step) opt.stream.step(a, log, inc.lstp);
    if (inc.lstp == opt.lastStep) throw LastStepDone();
  }
};

int ample(const Setup& setup, const Params& P, const RunOptions& opt) {
  RunLog log;
  Stopwatch total;
  Analysis an = setup.setupGrid(P);                                  // setupGrid
  an.name = setup.name;
  checkAnalysis(an);
  if (an.geostatic) applyGeostatic(an);                              // K0 stress (InputError: exit 2)
  prepareOutput(opt.outDir);
  startStepFiles(opt.outDir, an, log);                               // rows appended after each step
  log.notes += looseTolWarning(an);                                  // tol > 1e-3: allowed, but said
  auto stop = [&](const std::string& why) {                          // the run cannot go on
    if (!log.steps.empty() && !log.steps.back().converged) log.steps.back().seconds = log.stepClock.lap();
    restoreConverged(an.mpData);
    log.converged = false;
    log.message = why;
    std::cerr << "ample: " << setup.name << ": " << why << "\n"
              << "ample: output kept up to the last converged load step ("
              << log.lastConverged << ") in " << opt.outDir << "\n";
  };
  RunState x;
  const RunHooks hooks(an, log, opt, x);                             // the extensions it asks for
  if (opt.stream.start) opt.stream.start(an);
  try {
    solve(an, hooks);                                                // the loops (ample.cpp)
  } catch (const LastStepDone&) {                                    // the tests' opt.lastStep
  } catch (const RunError& e) {
    stop(e.what() + whatToTry(e, an, lstpsMax(P)));
  } catch (const std::bad_alloc&) {
    stop("out of memory in load step " + std::to_string(log.lastConverged + 1) +
         ": try fewer cells or points (the setup's grid parameters, mp) or OMP_NUM_THREADS=1");
  }
  log.t.total = total.lap();
  writeOutput(setup, P, an, log, opt.outDir, opt.quiet);
  std::cerr << log.notes;                                            // after a stop's reason (stop)
  return log.converged ? 0 : 1;
}

void solveRun(Analysis& an, RunLog& log, const RunOptions& opt) {
  RunState x;
  const RunHooks hooks(an, log, opt, x);
  try {
    solve(an, hooks);
  } catch (const LastStepDone&) {                                    // the tests' opt.lastStep
  }
}

//--------------------------------------------------------------------------
// the helpers of the page above
//--------------------------------------------------------------------------

// a general mesh (docs/meshes.md): every point in a cell, and none of what needs the
// regular grid: GIMP domains, the ghost penalty's faces, the implicit boundaries' cut cells
static void checkGeneralMesh(const Analysis& an) {
  const std::string mesh = std::string("the background mesh is a ") + meshName(an.mesh) +
                           " of " + std::to_string(an.mesh.nels()) + " cells";
  if (an.boundaries.has_value())
    throw InputError("implicit boundaries ([Boundaries]) need the regular grid (cutCells); " + mesh);
  if (an.ghost > 0) throw InputError("ghost=" + std::to_string(an.ghost) + ": the ghost penalty "
                                     "needs the regular grid (its faces); " + mesh + "; use ghost=0");
  for (size_t p = 0; p < an.mpData.size(); ++p) {
    const MaterialPoint& mp = an.mpData[p];
    if (mp.mpType == MpType::GIMP)
      throw InputError("mpType=2 (GIMP) needs the regular grid; " + mesh +
                       " (use mpType=1 MPM, 3 CPDI1 or 4 CPDI2)");
    if (findCell(an.mesh, mp.mpC) < 0)
      throw InputError("material point " + std::to_string(p) + " at (" + std::to_string(mp.mpC(0)) +
                       ", " + std::to_string(mp.mpC(1)) + ") lies in no cell of " + mesh.substr(4));
  }
  if (an.mpData.empty()) throw InputError("the setup has no material points: its body is empty or lies outside its grid (check the size parameters in `ample " + an.name + " --help`)");
}

// a setup's problem must be consistent before any work (InputError: exit 2)
static void checkAnalysis(const Analysis& an) {
  for (const BC& c : an.mesh.bc)
    if (c.dof < 0 || c.dof >= an.mesh.nDoF())
      throw InputError("boundary condition on degree of freedom " + std::to_string(c.dof) +
                       ", which does not exist: allowed [0, " + std::to_string(an.mesh.nDoF() - 1) + "]");
  if (an.fem && an.mesh.regular())
    throw InputError("the finite element mode (fem=1) moves the mesh: it needs a general mesh "
                     "(generalMesh), not the regular grid, whose cell search uses its spacing");
  if (an.fem)
    for (const MaterialPoint& mp : an.mpData)
      if (mp.mpType != MpType::MPM)
        throw InputError("the finite element mode (fem=1) takes standard points (mpType=1 MPM) "
                         "as its integration points");
  if (an.locking == Locking::Fbar && !fbarRefusal(an.mesh, an.fem).empty())
    throw InputError(fbarRefusal(an.mesh, an.fem));
  if (!an.mesh.regular()) return checkGeneralMesh(an);
  const Vector2d lo = an.mesh.origin,
                 hi = lo + Vector2d(an.mesh.nelsx * an.mesh.h(0), an.mesh.nelsy * an.mesh.h(1));
  for (size_t p = 0; p < an.mpData.size(); ++p) {
    const Vector2d& x = an.mpData[p].mpC;
    if ((x - lo).minCoeff() < 0 || (hi - x).minCoeff() < 0)
      throw InputError("material point " + std::to_string(p) + " at (" + std::to_string(x(0)) + ", " +
                       std::to_string(x(1)) + ") lies outside the background grid");
  }
  if (an.mpData.empty()) throw InputError("the setup has no material points: its body is empty or lies outside its grid (check the size parameters in `ample " + an.name + " --help`)");
}

// a tol above 1e-3 is allowed (its range is (0, 1)) but not what the paper means by converged:
// the warning, a line for stderr (log.notes: said after a stop's reason), or "" at a tighter tol
static std::string looseTolWarning(const Analysis& an) {
  if (an.tol <= 1e-3) return "";
  std::ostringstream s;
  s << "ample: " << an.name << ": warning: tol=" << an.tol << " accepts load steps whose "
    << "out-of-balance force is up to " << an.tol << " of the load (eq 35); the paper's is 1e-9\n";
  return s.str();
}

// the largest lstps the setup allows (what to try after a failure must be a valid input)
static int lstpsMax(const Params& P) {
  for (const Param& p : P)
    if (p.name == "lstps") return int(std::min(p.hi, 1e6));
  return 1;
}

// the start of load step lstp: its progress line, its clock, the setup's hook
static void startStep(Analysis& an, int lstp, RunLog& log, bool quiet) {
  if (!quiet) std::printf("%s: load step %d of %d\n", an.name.c_str(), lstp, an.lstps);
  std::fflush(stdout);  // seen per step also when stdout is a file
  log.stepClock.lap();
  if (an.beforeStep) an.beforeStep(an, lstp);
}

// remedy: the ghost penalty of the edge cells of this step, empty when ghost = 0
// or before the first load step that failed without it (an.ghostFrom)
static SpMat ghostPenaltyOf(const Analysis& an) {
  if (!(an.ghost > 0) || an.ghostFrom == 0) return SpMat();
  double E = 0.0;                                                 // the stiffest point's E
  for (const MaterialPoint& mp : an.mpData) E = std::max(E, mp.mCst.E);
  return ghostPenalty(an.mesh, an.ghost, E);
}

// one Newton-Raphson pass: residuals.csv row, progress line; a NaN or Inf stops
// the step, naming the first point whose stress is not finite
static void recordPass(RunLog& log, const std::vector<MaterialPoint>& mpData, int lstp, int NRit,
                       double fErr, bool quiet) {
  log.residuals.push_back({lstp, NRit, fErr});
  if (!quiet) std::printf("  iteration %2d  NR error %10.3e\n", NRit + 1, fErr);
  if (std::isfinite(fErr)) return;
  std::string where = "no material point has a non-finite stress: look at the nodal forces";
  for (size_t p = 0; p < mpData.size(); ++p)
    if (!mpData[p].sig.allFinite() || !mpData[p].F.allFinite()) {
      where = "first at material point " + std::to_string(p) + " (x = " +
              std::to_string(mpData[p].mpC(0)) + ", y = " + std::to_string(mpData[p].mpC(1)) + ")";
      break;
    }
  throw NewtonFailure("load step " + std::to_string(lstp) + ", Newton-Raphson pass " +
                      std::to_string(NRit) + ": the residual is not finite (NaN or Inf), " + where,
                      Failure::NotFinite);
}

// a converged state in which a point's det F <= 0 (its volume V = det F V0, eq 15, would
// be zero or negative) is no state at all: only a loose tol or too large a step accepts one
static void checkNotInverted(const std::vector<MaterialPoint>& mpData, int lstp, double fErr) {
  for (size_t p = 0; p < mpData.size(); ++p) {
    const double J = mpData[p].F.determinant();
    if (J > 0) continue;
    char msg[200];
    std::snprintf(msg, sizeof msg, "load step %d: material point %zu is inverted (det F = %.3e <= 0) "
                  "in the state accepted at fErr = %.3e", lstp, p, J, fErr);
    throw NewtonFailure(msg, Failure::Inverted);
  }
}

// a step that ended with fErr > tol stops (or is retried). The message says why when it can:
// the residual was still falling fast (more passes may well converge), or it had stalled
// at its round-off floor (roundOffFloor.h: then no number of passes helps, a larger tol
// does, and the message names one). Stalled: the last three residuals of the step within
// a factor 3 of each other; at the floor: no more than 10 times the estimate (the
// estimate is good to a factor of a few: roundOffFloor.h) and at most maxFloor = 1e-6: a
// step whose forces balance to fewer than six digits has not converged, whatever the
// estimate says (an estimate near 1 means that eq 35's denominator is round-off itself,
// e.g. E = 1e30 against a load of order 1). uvw and load = fext + frct (+ IB reactions) of
// the last pass are only read when the step failed. acceptFloor (--accept-floor, off by
// default) accepts a step stalled at its floor as converged, said on stderr at the run's end
// (log.notes); it acts only where the step has failed, so no run that converges changes.
static void explainFailure(const Analysis& an, RunLog& log, int lstp, int NRit, double fErr,
                           const Eigen::VectorXd& uvw, const Eigen::VectorXd& load, bool acceptFloor) {
  if (fErr <= an.tol) return;
  const double maxFloor = 1e-6;                                    // the largest credible floor
  char msg[600];
  int n = std::snprintf(msg, sizeof msg, "load step %d did not converge: fErr = %.3e > tol = %.1e "
                        "after %d Newton-Raphson passes (NRitMax = %d)", lstp, fErr, an.tol, NRit, an.NRitMax);
  Failure kind = Failure::NotConverged;
  const size_t k = log.residuals.size();
  const bool three = k >= 3 && log.residuals[k - 3].lstp == lstp;  // the step's last three passes
  const double r0 = three ? log.residuals[k - 3].fErr : fErr, r1 = three ? log.residuals[k - 2].fErr : fErr;
  const double hi = std::max({r0, r1, fErr}), lo = std::min({r0, r1, fErr});
  const bool stalled = three && hi < 3 * lo;
  const double floor = stalled || !three ? roundOffFloor(an.mpData, uvw, load) : 0.0;
  if ((stalled || !three) && hi <= 10 * floor && hi <= maxFloor) {
    kind = Failure::AtFloor;
    const int tolExp = int(std::ceil(std::log10(2 * hi)));         // 10^tolExp >= 2 x the stall
    n += stalled ? std::snprintf(msg + n, sizeof msg - n, "; the residual stalled at %.2e (its last three "
                                 "passes %.2e, %.2e, %.2e), its estimated round-off floor is %.1e", hi, r0, r1,
                                 fErr, floor)
                 : std::snprintf(msg + n, sizeof msg - n, "; the residual %.2e is within 10 times its "
                                 "estimated round-off floor %.1e", hi, floor);
    std::snprintf(msg + n, sizeof msg - n, " (ample/solver/roundOffFloor.h): more passes will not help, a tol "
                  "above the floor would pass, e.g. tol=1e%d", tolExp);
    if (acceptFloor && stalled) {                                  // said after the outcome (notes)
      char note[300];
      std::snprintf(note, sizeof note, "ample: load step %d accepted at its round-off floor (--accept-floor): "
                    "fErr = %.3e > tol = %.1e, stalled at %.2e, estimated floor %.1e\n",
                    lstp, fErr, an.tol, hi, floor);
      log.notes += note;
      return;
    }
  } else if (an.NRitMax < 10 && !(three && fErr < r1 && r1 < r0 && fErr < 1e-3) &&
             !(stalled && hi <= maxFloor)) {
    kind = Failure::StillFalling;                                  // too few passes to tell
    std::snprintf(msg + n, sizeof msg - n, "; %d passes are too few for Newton-Raphson to converge "
                  "or show a pattern: try the paper's NRitMax=10", an.NRitMax);
  } else if (stalled && hi <= maxFloor) {
    kind = Failure::AtFloor;                                       // a tol advised, never accepted
    std::snprintf(msg + n, sizeof msg - n, "; the residual stalled at %.2e, below 1e-6 but above its "
                  "estimated round-off floor %.1e: a tol above the stall would pass, e.g. tol=1e%d", hi,
                  floor, int(std::ceil(std::log10(2 * hi))));
  } else if (stalled) {
    kind = Failure::Stalled;
    std::snprintf(msg + n, sizeof msg - n, "; the residual stalled at %.2e%s", hi,
                  hi > maxFloor ? ", far above round-off (a floor is at most 1e-6)" : "");
  } else if (three && fErr < r1 && r1 < r0 && fErr < 1e-3 && an.NRitMax < 1000) {
    kind = Failure::StillFalling;
    std::snprintf(msg + n, sizeof msg - n, "; the residual was still falling (%.1e, %.1e, %.1e): "
                  "more passes may converge, e.g. NRitMax=%d", r0, r1, fErr, std::min(std::max(20, 2 * an.NRitMax), 1000));
  }
  throw NewtonFailure(msg, kind);
}

// one steps.csv row per attempt at a load step (its seconds are set at its end); the solver's
// notes (an LU fallback) join the run's, said after its outcome
static void recordStep(RunLog& log, const Increment& inc, int NRit, double fErr, FreeSystem& Kff,
                       bool converged) {
  log.notes += Kff.notes;
  Kff.notes.clear();
  log.totalNRit += NRit;
  log.solverAnalyses = Kff.builds;                                   // so far (summary.json)
  log.luFallbacks = Kff.fallbacks;
  log.factorisations = Kff.factorisations;
  log.steps.push_back({inc.lstp, inc.lf1, NRit, fErr, converged, 0.0, Kff.negativePivots});
}

}  // namespace ample
