//--------------------------------------------------------------------------
// ample — the analysis: load steps, Newton-Raphson iterations, material points
//--------------------------------------------------------------------------
// [AMPLE] fig 4. solve is the load-step loop, loadStep one load step: the
// basis, the loads, the free dofs, the Newton-Raphson loop (eqs 29-35) and
// the point update. Each "hooks." call is where an extension joins (hooks.h);
// a plain run's hooks are the core functions (elemMPinfo, detFDoFs, solveFree,
// detMPs, checkConverged, updateGIMPDomain) or empty (those marked "hook:").
//--------------------------------------------------------------------------
#include "ample.h"
#include "detExtForce.h"
#include "updateMPs.h"
#include <cfloat>
#include <cstdio>

namespace ample {

static void checkHooks(const Analysis& an, const Hooks& hooks);
static std::vector<BC> scaled(std::vector<BC> bc, double factor);
static double normalisedResidual(const Eigen::VectorXd& oobf, const Eigen::VectorXd& fext,
                                 const Eigen::VectorXd& frct, const Eigen::VectorXd& frctLast, int NRit);

void solve(Analysis& an, const Hooks& hooks) {
  checkHooks(an, hooks);                                            // what an needs is there
  for (int lstp = 1; lstp <= an.lstps; ++lstp) {                    // load steps
    const Increment inc{lstp, double(lstp - 1) / an.lstps, double(lstp) / an.lstps};
    hooks.startStep(an, inc);                                       // hook: progress
    try {
      loadStep(an, inc, hooks);                                     // below
    } catch (const RunError& e) {                                   // not converged, singular
      hooks.failedStep(an, inc, e);                                 // hook: retry (remedies); a
                                                                    // plain run's: the run stops
    }
    hooks.endStep(an, inc);                                         // hook: postPro, log
  }
}

void loadStep(Analysis& an, const Increment& inc, const Hooks& hooks) {
  Mesh& mesh = an.mesh;
  std::vector<MaterialPoint>& mpData = an.mpData;
  const int nDoF = mesh.nDoF();
  hooks.elemMPinfo(mesh, mpData, an.fem);                           // basis functions
  Eigen::VectorXd fext = detExtForce(nDoF, an.g, mpData) * inc.lf1; // external force
  hooks.stepTerms(an, inc, fext);                                   // hook: body force, ...
  const std::vector<BC> bc = scaled(mesh.bc, inc.share);            // the step's increments
  const std::vector<int> fd = hooks.detFDoFs(mesh, mpData);         // free dofs
  Eigen::VectorXd uvw = Eigen::VectorXd::Zero(nDoF), frct = Eigen::VectorXd::Zero(nDoF);
  Eigen::VectorXd fbnd = Eigen::VectorXd::Zero(nDoF), oobf = fext;  // (fbnd: the hooks' reactions)
  DetMPsOut mps;                                                    // fint, Kt
  double fErr = 1.0;
  int NRit = 0;
  while ((fErr > an.tol && NRit < an.NRitMax) || NRit < 2) {       // Newton-Raphson
    const LinSolveOut ls = linSolve(bc, mps.Kt, oobf, NRit, fd, hooks);
    uvw += ls.duvw;                                                 // eq 29
    frct += ls.drct;
    hooks.detMPs(uvw, mpData, an.formulation, mps);                 // fint, Kt (eqs 30-31)
    hooks.passTerms(uvw, mps, fbnd);                                // hook: ghost penalty, ...
    oobf = fext - mps.fint + frct;                                  // out of balance force
    fErr = normalisedResidual(oobf, fext, frct + fbnd, an.frct, NRit);  // eq 35
    hooks.afterPass(an, inc, NRit, fErr);                           // hook: progress, log
    NRit++;
  }
  hooks.checkConverged(an, inc, NRit, fErr, uvw, fext + frct + fbnd);  // fErr > tol: throws
  an.frct = frct + fbnd;                                            // reactions
  an.uvw = uvw;
  updateMPs(mesh, uvw, mpData, hooks);                              // points, mesh reset
  hooks.afterUpdate(an, inc, NRit, fErr);                           // hook: FE mode, split, log
}

void checkConverged(const Analysis& an, const Increment& inc, int NRit, double fErr,
                    const Eigen::VectorXd& /*uvw*/, const Eigen::VectorXd& /*load*/) {
  if (fErr <= an.tol) return;
  char msg[200];
  std::snprintf(msg, sizeof msg, "load step %d did not converge: fErr = %.3e > tol = %.1e after %d "
                "Newton-Raphson passes (NRitMax = %d)", inc.lstp, fErr, an.tol, NRit, an.NRitMax);
  throw NewtonFailure(msg, Failure::NotConverged);
}

// an analysis that asks for an extension (a setup's beforeStep or afterStep, a body force,
// the finite element mode, implicit boundaries, a remedy, CPDI points, a general mesh or
// another domain update) runs only with the program's hooks (solveRun, setups/program/run.h): refused
// here, not solved wrongly without them
static void checkHooks(const Analysis& an, const Hooks& hooks) {
  bool needs = an.beforeStep || an.afterStep || an.bodyForce || an.fem || an.boundaries.has_value() ||
               an.ghost > 0 || an.substeps > 0 || an.split > 0 || an.domainUpdate != DomainUpdate::Uii ||
               !an.mesh.regular();
  for (const MaterialPoint& mp : an.mpData) needs = needs || isCPDI(mp);
  if (needs && !hooks.program())
    throw InputError(an.name + ": this analysis needs the program's hooks (a setup's beforeStep/afterStep, "
                     "bodyForce, fem, boundaries, ghost, substeps, split, CPDI, a general mesh or domainUpdate): run it "
                     "with solveRun");
}

// the prescribed increments of this step (or of a part of it)
static std::vector<BC> scaled(std::vector<BC> bc, double factor) {
  for (BC& c : bc) c.value *= factor;
  return bc;
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

}  // namespace ample
