//--------------------------------------------------------------------------
// ample — the analysis: load steps, Newton-Raphson iterations, material points
//--------------------------------------------------------------------------
// Seed 002 figs 4-5 and sec 3.5. For each load step lstp = 1..lstps:
//   elemMPinfo (basis at the start of the step) -> detExtForce (scaled by
//   lstp/lstps) -> detFDoFs -> Newton-Raphson loop { linSolve -> detMPs ->
//   oobf = fext - fint + frct, fErr = |oobf| / |fext + frct| (eq 35) } while
//   (fErr > tol and NRit < NRitMax) or NRit < 2 -> updateMPs -> postPro.
// A step that ends with fErr > tol (or a NaN, or a singular stiffness) stops the
// run (exit 1): the state of the last converged step is kept and written, the
// failure is named on stderr — unless substeps > 0: then the step is retried
// in halves, up to substeps times (a remedy; the default 0 is the paper's way).
// See ample.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "ample.h"
#include "constitutive/Hooke3d.h"
#include "detExtForce.h"
#include "detFDoFs.h"
#include "detMPs.h"
#include "elemMPinfo.h"
#include "errors.h"
#include "ghostPenalty.h"
#include "linSolve.h"
#include "plotting/postPro.h"
#include "plotting/writeOutput.h"
#include "updateMPs.h"
#include <cfloat>
#include <cstdio>
#include <iostream>

namespace ample {

static double largestE(const std::vector<MaterialPoint>& mpData) {
  double E = 0.0;
  for (const MaterialPoint& mp : mpData) E = std::max(E, mp.mCst(0));
  return E;
}

// the message for a residual that is NaN or Inf: where it first shows
static std::string notFinite(const std::vector<MaterialPoint>& mpData, int lstp, int NRit) {
  std::string where = "no material point has a non-finite stress: look at the nodal forces";
  for (size_t p = 0; p < mpData.size(); ++p)
    if (!mpData[p].sig.allFinite() || !mpData[p].F.allFinite()) {
      where = "first at material point " + std::to_string(p) + " (x = " +
              std::to_string(mpData[p].mpC(0)) + ", y = " + std::to_string(mpData[p].mpC(1)) + ")";
      break;
    }
  return "load step " + std::to_string(lstp) + ", Newton-Raphson pass " + std::to_string(NRit) +
         ": the residual is not finite (NaN or Inf), " + where;
}

Eigen::VectorXd solveLoadStep(Analysis& an, int lstp, double lf, double bcScale, RunLog& log,
                              bool quiet) {
  Mesh& mesh = an.mesh;
  const int nDoF = mesh.nDoF();
  Stopwatch sw;
  elemMPinfo(mesh, an.mpData);                                   log.t.elemMPinfo += sw.lap();
  const Eigen::VectorXd fext = detExtForce(nDoF, an.g, an.mpData) * lf; log.t.detExtForce += sw.lap();
  std::vector<BC> bc = mesh.bc;                                  // prescribed increments of
  for (BC& c : bc) c.value *= bcScale;                           // this (part of a) step
  Eigen::VectorXd oobf = fext, frct = Eigen::VectorXd::Zero(nDoF), uvw = frct;
  const std::vector<int> fd = detFDoFs(mesh);                    log.t.detFDoFs += sw.lap();
  double fErr = 1.0;
  int NRit = 0;
  SpMat Kt = stiffnessPattern(nDoF, an.mpData);                  // sparsity of this step
  FreeSystem Kff;                                                // Kt(fd,fd) and its analysis
  SpMat Kgp, Ksys;                                               // remedy: ghost penalty (off:
  if (an.ghost > 0) Kgp = ghostPenalty(mesh, an.ghost, largestE(an.mpData));  // empty)
  log.t.detMPs += sw.lap();
  try {
    while ((fErr > an.tol && NRit < an.NRitMax) || NRit < 2) {
      const SpMat& K = (an.ghost > 0 && NRit > 0) ? (Ksys = Kt + Kgp) : Kt;
      const LinSolveOut ls = linSolve(bc, K, oobf, NRit, fd, &Kff); log.t.linSolve += sw.lap();
      uvw += ls.duvw;
      frct += ls.drct;
      DetMPsOut mps = detMPs(uvw, an.mpData, an.formulation, std::move(Kt)); log.t.detMPs += sw.lap();
      Kt = std::move(mps.Kt);
      if (an.ghost > 0) mps.fint += Kgp * uvw;                   // penalty on the increment
      oobf = fext - mps.fint + frct;                             // eq 31 with reactions
      fErr = oobf.norm() / ((fext + frct).array() + DBL_EPSILON).matrix().norm();  // eq 35 (+eps)
      log.residuals.push_back({lstp, NRit, fErr});
      if (!quiet) std::printf("  iteration %2d  NR error %10.3e\n", NRit + 1, fErr);
      if (!std::isfinite(fErr)) throw NewtonFailure(notFinite(an.mpData, lstp, NRit));
      NRit++;
    }
  } catch (const RunError& e) {                                  // e.g. a singular stiffness
    log.totalNRit += NRit;
    log.steps.push_back({lstp, lf, NRit, fErr, false, 0.0});
    throw NewtonFailure(e.what());
  }
  log.totalNRit += NRit;
  log.steps.push_back({lstp, lf, NRit, fErr, fErr <= an.tol, 0.0});
  an.frct = frct;
  if (!(fErr <= an.tol)) {
    char msg[200];
    std::snprintf(msg, sizeof msg, "load step %d did not converge: fErr = %.3e > tol = %.1e "
                  "after %d Newton-Raphson passes (NRitMax = %d)", lstp, fErr, an.tol, NRit, an.NRitMax);
    throw NewtonFailure(msg);
  }
  return uvw;
}

// load factors lf0 -> lf1 of load step lstp; when Newton fails and sub-division is
// allowed (an.substeps > depth), restore the converged state and take two halves
static void advance(Analysis& an, int lstp, double lf0, double lf1, int depth, RunLog& log,
                    bool quiet) {
  Eigen::VectorXd uvw;
  try {
    uvw = solveLoadStep(an, lstp, lf1, (lf1 - lf0) * an.lstps, log, quiet);
  } catch (const NewtonFailure& e) {
    if (depth >= an.substeps) throw;
    restoreConverged(an.mpData);
    if (!quiet) std::printf("  %s: retrying with half the increment\n", e.what());
    advance(an, lstp, lf0, 0.5 * (lf0 + lf1), depth + 1, log, quiet);
    advance(an, lstp, 0.5 * (lf0 + lf1), lf1, depth + 1, log, quiet);
    return;
  }
  Stopwatch sw;
  updateMPs(an.mesh, uvw, an.domainUpdate, an.mpData);           log.t.updateMPs += sw.lap();
}

void loadStep(Analysis& an, int lstp, RunLog& log, bool quiet) {
  if (an.beforeStep) an.beforeStep(an, lstp);
  advance(an, lstp, double(lstp - 1) / an.lstps, double(lstp) / an.lstps, 0, log, quiet);
  if (an.afterStep) an.afterStep(an, lstp);
}

void restoreConverged(std::vector<MaterialPoint>& mpData) {
  for (MaterialPoint& mp : mpData) {
    mp.F = mp.Fn;
    mp.epsE = mp.epsEn;
    mp.sig = Hooke3d(mp.epsEn, mp.mCst).Ksig / mp.Fn.determinant();  // stored state is elastic
  }
}

// a setup's problem must be consistent before any work (InputError: exit 2)
static void checkAnalysis(const Analysis& an) {
  for (const BC& c : an.mesh.bc)
    if (c.dof < 0 || c.dof >= an.mesh.nDoF())
      throw InputError("boundary condition on degree of freedom " + std::to_string(c.dof) +
                       ", which does not exist: allowed [0, " + std::to_string(an.mesh.nDoF() - 1) + "]");
  const Vector2d lo = an.mesh.origin,
                 hi = lo + Vector2d(an.mesh.nelsx * an.mesh.h(0), an.mesh.nelsy * an.mesh.h(1));
  for (size_t p = 0; p < an.mpData.size(); ++p) {
    const Vector2d& x = an.mpData[p].mpC;
    if ((x - lo).minCoeff() < 0 || (hi - x).minCoeff() < 0)
      throw InputError("material point " + std::to_string(p) + " at (" + std::to_string(x(0)) + ", " +
                       std::to_string(x(1)) + ") lies outside the background grid");
  }
  if (an.mpData.empty()) throw InputError("the setup has no material points");
}

int ample(const Setup& setup, const Params& P, const RunOptions& opt) {
  Stopwatch total, sw;
  Analysis an = setup.setupGrid(P);                              // setupGrid
  checkAnalysis(an);
  RunLog log;
  prepareOutput(opt.outDir);
  try {
    for (int lstp = 1; lstp <= an.lstps; ++lstp) {               // load steps
      if (!opt.quiet) std::printf("%s: load step %d of %d\n", setup.name, lstp, an.lstps);
      sw.lap();
      loadStep(an, lstp, log, opt.quiet);
      Stopwatch swP;
      postPro(an.mesh, an.mpData, lstp, opt.vtkEvery, opt.outDir); log.t.postPro += swP.lap();
      log.steps.back().seconds = sw.lap();
      log.lastConverged = lstp;
    }
  } catch (const RunError& e) {
    if (!log.steps.empty() && !log.steps.back().converged) log.steps.back().seconds = sw.lap();
    restoreConverged(an.mpData);
    log.converged = false;
    log.message = e.what();
    std::cerr << "ample: " << setup.name << ": " << e.what() << "\n"
              << "ample: output kept up to the last converged load step ("
              << log.lastConverged << ") in " << opt.outDir << "\n";
  }
  log.t.total = total.lap();
  writeOutput(setup, P, an, log, opt.outDir, opt.quiet);
  return log.converged ? 0 : 1;
}

}  // namespace ample
