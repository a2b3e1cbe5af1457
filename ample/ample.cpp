//--------------------------------------------------------------------------
// ample — the analysis: load steps, Newton-Raphson iterations, material points
//--------------------------------------------------------------------------
// [AMPLE] figs 4-5 and sec 3.5, on one page (the function ample below):
//   setupGrid
//   for each load step lstp = 1..lstps
//     elemMPinfo (basis at the start of the step), detExtForce (scaled by
//     lstp/lstps; plus detBodyForce at lstp/lstps if the setup gives b(X, lf)), detFDoFs
//     Newton-Raphson: while (fErr > tol and NRit < NRitMax) or NRit < 2
//       linSolve, detMPs, oobf = fext - fint + frct, fErr (eq 35)
//     updateMPs (the finite element mode, an.fem, moves the mesh with the
//     nodes here: the one line where FEM and MPM differ)
//     postPro
// A step that ends with fErr > tol (or a NaN, or a singular stiffness) stops the
// run (exit 1): the state of the last converged step is kept and written, the
// failure is named on stderr, first: what else a run says there (a loose tol, a
// step accepted at its floor) is kept in log.notes and follows it. Two remedies,
// off by default: loadSteps.retry is the one line of both in the handler of a
// failed step (ghost > 0: retry it with the ghost penalty, on from then;
// substeps > 0: retry it in halves), and
// addGhostPenalty the one line that applies the penalty in the Newton loop; a
// third, split > 0, is splitPoints after updateMPs (stretched GIMP points cut in two). The
// implicit boundaries of [Boundaries] (ibStiffness.h; none by default: nothing changes)
// are three named lines: ibStiffness once per step, addImplicitBoundaries after
// detMPs, moveBoundaries after updateMPs. Every timed call goes through timed(seconds, f,
// args...) (plotting/runLog.h), which is f(args...) with a stopwatch around it.
// See ample.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "ample.h"
#include "ample/meshes/cellSearch.h"
#include "detExtForce.h"
#include "detFDoFs.h"
#include "detMPs.h"
#include "elemMPinfo.h"
#include "errors.h"
#include "ample/remedies/ghostPenalty.h"
#include "ample/boundaries/ibStiffness.h"
#include "linSolve.h"
#include "ample/remedies/loadSteps.h"
#include "ample/remedies/splitPoints.h"
#include "plotting/postPro.h"
#include "plotting/writeOutput.h"
#include "ample/solver/roundOffFloor.h"
#include "updateMPs.h"
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <new>
#include <sstream>

namespace ample {

// helpers of this page (defined below it): bookkeeping, not algorithm
static void checkAnalysis(const Analysis& an);
static std::string looseTolWarning(const Analysis& an);
static int lstpsMax(const Params& P);
static void startStep(Analysis& an, int lstp, RunLog& log, bool quiet);
static std::vector<BC> scaled(std::vector<BC> bc, double factor);
static SpMat ghostPenaltyOf(const Analysis& an);
static ImplicitBoundaries implicitBoundariesOf(const Analysis& an, const Increment& inc);
static void recordPass(RunLog& log, const std::vector<MaterialPoint>& mpData, int lstp, int NRit,
                       double fErr, bool quiet);
static double normalisedResidual(const Eigen::VectorXd& oobf, const Eigen::VectorXd& fext,
                                 const Eigen::VectorXd& frct, const Eigen::VectorXd& frctLast, int NRit);
static void checkConverged(const Analysis& an, RunLog& log, int lstp, int NRit, double fErr,
                           const Eigen::VectorXd& uvw, const Eigen::VectorXd& load, bool acceptFloor);
static void recordStep(RunLog& log, const Increment& inc, int NRit, double fErr, FreeSystem& Kff,
                       bool converged);
static void checkNotInverted(const std::vector<MaterialPoint>& mpData, int lstp, double fErr);

int ample(const Setup& setup, const Params& P, const RunOptions& opt) {
  RunLog log;
  Stopwatch total;
  Analysis an = setup.setupGrid(P);                                  // setupGrid
  an.name = setup.name;
  checkAnalysis(an);
  prepareOutput(opt.outDir);
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
  try {
    solve(an, log, opt);                                             // the loops, below
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

void solve(Analysis& an, RunLog& log, const RunOptions& opt) {
  Mesh& mesh = an.mesh;
  std::vector<MaterialPoint>& mpData = an.mpData;
  Timers& T = log.t;
  const int nDoF = mesh.nDoF();
  LoadSteps loadSteps(an.lstps, an.substeps, opt.lastStep);          // lstp = 1 .. lstps
  FreeSystem Kff;                                                    // Kt(fd,fd), analysed once
  Kff.choice = an.solver;                                            // SparseLU, or LDLT if symmetric
  Kff.nodeCoord = &mesh.coord;                                       // (LDLT_HALVES cuts by them)
  for (Increment inc; loadSteps.next(inc);) {                        // load steps
    const int lstp = inc.lstp;
    if (inc.first) startStep(an, lstp, log, opt.quiet);              // progress, setup's hook
    timed(T.elemMPinfo, opt.basisLoop, mesh, mpData, an.fem);     // elemMPinfo: basis functions
    Eigen::VectorXd fext = timed(T.detExtForce, detExtForce, nDoF, an.g, mpData) * inc.lf1;
    if (an.bodyForce) fext += timed(T.detExtForce, detBodyForce, nDoF, an.bodyForce, inc.lf1, mpData);
    const std::vector<BC> bc = scaled(mesh.bc, inc.bcScale(an.lstps));  // increments of this step
    const SpMat Kgp = ghostPenaltyOf(an);                            // remedy (off: empty)
    const ImplicitBoundaries ib = implicitBoundariesOf(an, inc);     // [Boundaries] (none: empty)
    const std::vector<int> fd = timed(T.detFDoFs, detFDoFs, mesh, mpData, StiffnessSources{&Kgp, &ib.K},
                                          an.lone);
    Eigen::VectorXd uvw = Eigen::VectorXd::Zero(nDoF), frct = uvw, oobf = fext, fib = uvw;
    DetMPsOut mps;                                                   // fint, Kt (and bEn) of the step
    mps.Kt = timed(T.detMPs, stiffnessPattern, nDoF, mpData);        // Kt's sparsity, once
    double fErr = 1.0;
    int NRit = 0;
    try {
      while ((fErr > an.tol && NRit < an.NRitMax) || NRit < 2) {     // Newton-Raphson
        const LinSolveOut ls = timed(T.linSolve, linSolve, bc, mps.Kt, oobf, NRit, fd, &Kff);
        uvw += ls.duvw;                                              // eq 29
        frct += ls.drct;
        timed(T.detMPs, [&] { opt.pointLoop(uvw, mpData, an.formulation, mps); });  // detMPs: fint, Kt
        addGhostPenalty(Kgp, uvw, mps.Kt, mps.fint);                 // remedy (off: nothing)
        fib = addImplicitBoundaries(ib, uvw, mps.Kt, mps.fint);      // [Boundaries] (none: 0)
        oobf = fext - mps.fint + frct;                               // eq 31 with reactions
        fErr = normalisedResidual(oobf, fext, frct + fib, an.frct, NRit);  // eq 35, IB reactions too
        recordPass(log, mpData, lstp, NRit, fErr, opt.quiet);        // throws on NaN
        NRit++;
      }
      checkConverged(an, log, lstp, NRit, fErr, uvw, fext + frct + fib, opt.acceptFloor);  // fErr > tol: throws
      checkNotInverted(mpData, lstp, fErr);                          // det F <= 0 accepted: throws
    } catch (const RunError& e) {                                    // no convergence, NaN, singular
      recordStep(log, inc, NRit, fErr, Kff, false);
      loadSteps.retry(inc, e, an, opt.quiet);                        // remedies (off: rethrows e)
      continue;
    }
    recordStep(log, inc, NRit, fErr, Kff, true);
    an.frct = frct + fib;                                            // reactions, IB ones too
    an.uvw = uvw;
    an.ibForce = boundaryForces(ib, uvw, int(an.boundaries.size()));  // [Boundaries] (none: empty)
    timed(T.updateMPs, updateMPs, mesh, uvw, an.domainUpdate, mpData);
    if (an.fem) moveMesh(mesh, uvw);                                 // FEM: the mesh follows (MPM: reset)
    moveBoundaries(an.boundaries, lstp, inc.bcScale(an.lstps));      // [Boundaries]: by their du
    log.splits += splitPoints(mesh, an.split, mpData, opt.quiet);    // remedy (off: nothing)
    if (!inc.last) continue;                                         // (remedy: a first half)
    if (an.afterStep) an.afterStep(an, lstp);                        // setup's hook
    timed(T.postPro, postPro, mesh, mpData, uvw, lstp, opt.vtkEvery, opt.outDir, opt.vtkFormat, opt.vtkGridEvery || an.fem || an.gridMoves);
    log.steps.back().seconds = log.stepClock.lap();
    log.lastConverged = lstp;
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
  if (!an.boundaries.empty())
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

// the prescribed increments of this step (or of a part of it)
static std::vector<BC> scaled(std::vector<BC> bc, double factor) {
  for (BC& c : bc) c.value *= factor;
  return bc;
}

// remedy: the ghost penalty of the edge cells of this step, empty when ghost = 0
// or before the first load step that failed without it (an.ghostFrom)
static SpMat ghostPenaltyOf(const Analysis& an) {
  if (!(an.ghost > 0) || an.ghostFrom == 0) return SpMat();
  double E = 0.0;                                                 // the stiffest point's E
  for (const MaterialPoint& mp : an.mpData) E = std::max(E, mp.mCst(0));
  return ghostPenalty(an.mesh, an.ghost, E);
}

// [Boundaries]: K_IB and f_IB of the implicit boundaries for this step (or its part, the
// share bcScale of the step's prescribed increments); empty when there are none
static ImplicitBoundaries implicitBoundariesOf(const Analysis& an, const Increment& inc) {
  return ibStiffness(an.mesh, an.boundaries, an.mpData, inc.lstp, inc.bcScale(an.lstps));
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

// eq 35: fErr = |oobf| / |fext + frct|, with DBL_EPSILON added to each entry of the
// denominator as the original. Pass 0 comes before the first solve, so frct is still
// 0: in a displacement-driven step (fext = 0, e.g. the stretch) the denominator would
// be ~1e-16 and fErr ~1e17. There, and only there, the reactions of the last
// converged step (frctLast) stand in. Pass 0 never ends the loop (NRit < 2), so no
// converged result changes, and a step with loads keeps the paper's pass-0 value
// ([Lagrangian] table 8).
static double normalisedResidual(const Eigen::VectorXd& oobf, const Eigen::VectorXd& fext,
                                 const Eigen::VectorXd& frct, const Eigen::VectorXd& frctLast, int NRit) {
  const bool noLoad = NRit == 0 && frctLast.size() == fext.size() &&
                      fext.norm() <= 1e-12 * frctLast.norm();
  const Eigen::VectorXd& r = noLoad ? frctLast : frct;
  return oobf.norm() / ((fext + r).array() + DBL_EPSILON).matrix().norm();
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
static void checkConverged(const Analysis& an, RunLog& log, int lstp, int NRit, double fErr,
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
  log.factorisations = Kff.factorisations, log.krylovSolves = Kff.krylovSolves, log.krylovIterations = Kff.krylovIterations;
  log.steps.push_back({inc.lstp, inc.lf1, NRit, fErr, converged, 0.0});
}

}  // namespace ample
