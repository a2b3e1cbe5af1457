//--------------------------------------------------------------------------
// linSolve — linear solve for the displacement and reaction increments
//--------------------------------------------------------------------------
// Seed 002 eq 29. See linSolve.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "linSolve.h"
#include "errors.h"
#include <cstdio>

namespace ample {

// Kt(fd,fd) symmetric to 1e-12 of its largest entry (the pattern is symmetric)
static bool symmetric(const SpMat& K) {
  const SpMat T = K.transpose();
  const double big = K.coeffs().cwiseAbs().maxCoeff();
  const SpMat D = K - T;
  return D.nonZeros() == 0 || D.coeffs().cwiseAbs().maxCoeff() <= 1e-12 * big;
}

// a symmetric solver (LDLT, LDLT_METIS, CHOLMOD) factorises K (no pivoting) and solves;
// false when it fails (an indefinite K for LL^T) or its solve is not accurate to 1e-10
template <class SymmetricSolver>
static bool symmetricSolve(SymmetricSolver& s, const SpMat& K, const Eigen::VectorXd& rhs, Eigen::VectorXd& x) {
  s.factorize(K);
  if (s.info() != Eigen::Success) return false;
  x = s.solve(rhs);
  return (K * x - rhs).norm() <= 1e-10 * rhs.norm();
}

// the chosen symmetric solver on S.Kff; false for LU and UMFPACK
static bool chosenSymmetricSolve(FreeSystem& S, const Eigen::VectorXd& rhs, Eigen::VectorXd& x) {
  switch (S.choice) {
    case LinearSolver::LDLT: return symmetricSolve(S.ldlt, S.Kff, rhs, x);
#ifdef AMPLE_HAVE_METIS
    case LinearSolver::LDLT_METIS: return symmetricSolve(S.ldltMetis, S.Kff, rhs, x);
#endif
#ifdef AMPLE_HAVE_SUITESPARSE
    case LinearSolver::CHOLMOD: return symmetricSolve(S.cholmod, S.Kff, rhs, x);
#endif
    default: return false;
  }
}

// numeric factorisation of S.Kff and the solve: SparseLU (solver=LU), UMFPACK, or a symmetric
// solver when Kff is symmetric and its solve succeeds (else SparseLU); RunError when LU fails
static Eigen::VectorXd factorisedSolve(FreeSystem& S, const Eigen::VectorXd& rhs) {
  const std::string singular = "): the problem is singular, e.g. a rigid-body mode without enough "
                               "boundary conditions or a nearly empty cell";
#ifdef AMPLE_HAVE_SUITESPARSE
  if (S.choice == LinearSolver::UMFPACK) {
    S.umfpack.factorize(S.Kff);                         // numeric factorisation only
    if (S.umfpack.info() != Eigen::Success)
      throw RunError("UMFPACK could not factorise the stiffness Kt(fd,fd) (status " +
                     std::to_string(S.umfpack.umfpackFactorizeReturncode()) + singular);
    return S.umfpack.solve(rhs);
  }
#endif
  if (S.choice != LinearSolver::LU) {                   // LDLT, LDLT_METIS, CHOLMOD
    Eigen::VectorXd x;
    if (symmetric(S.Kff) && chosenSymmetricSolve(S, rhs, x)) return x;
    if (S.fallbacks++ == 0)
      std::fprintf(stderr, "solver=%s: Kt(fd,fd) not symmetric to 1e-12, or its factorisation failed or was "
                           "inexact: SparseLU solves such passes\n", solverNames()[size_t(S.choice)].c_str());
  }
  if (!S.luAnalysed) S.lu.analyzePattern(S.Kff);        // once per pattern
  S.luAnalysed = true;
  S.lu.factorize(S.Kff);                                // numeric factorisation only
  if (S.lu.info() != Eigen::Success)
    throw RunError("SparseLU could not factorise the stiffness Kt(fd,fd) (" + S.lu.lastErrorMessage() + singular);
  return S.lu.solve(rhs);
}

LinSolveOut linSolve(const std::vector<BC>& bc, const SpMat& Kt, const Eigen::VectorXd& oobf,
                     int NRit, const std::vector<int>& fd, FreeSystem* cache) {
  // BEGIN EXERCISE linSolve
  const int nDoF = int(oobf.size()), nfd = int(fd.size());
  LinSolveOut out{Eigen::VectorXd::Zero(nDoF), Eigen::VectorXd::Zero(nDoF)};
  if (NRit == 0) return out;  // first pass only builds Kt and fint
  if (NRit == 1)
    for (const BC& c : bc) out.duvw(c.dof) = c.value;  // prescribed increments

  const Eigen::VectorXd Kd = Kt * out.duvw;             // Kt(:,bc) duvw(bc)
  if (nfd == 0) {                                       // every active dof is prescribed
    for (const BC& c : bc) out.drct(c.dof) = Kd(c.dof) - oobf(c.dof);
    return out;
  }
  FreeSystem local;                                     // no cache given: build it here
  FreeSystem& S = cache ? *cache : local;
  refillFreeSystem(Kt, fd, S);                          // S.Kff = Kt(fd,fd) (fast part)

  Eigen::VectorXd rhs(nfd);
  for (int r = 0; r < nfd; ++r) rhs(r) = oobf(fd[r]) - Kd(fd[r]);

  const Eigen::VectorXd x = factorisedSolve(S, rhs);
  const double res = (S.Kff * x - rhs).norm(), scale = rhs.norm() + 1e-300;
  if (!(res <= 1e-3 * scale))                           // a zero pivot: no solution exists
    throw RunError("the stiffness Kt(fd,fd) is singular (linear solve residual " +
                   std::to_string(res / scale) + " of the right-hand side): a rigid-body mode "
                   "without enough boundary conditions, or a nearly empty cell");
  for (int r = 0; r < nfd; ++r) out.duvw(fd[r]) = x(r);

  const Eigen::VectorXd Ku = Kt * out.duvw;
  for (const BC& c : bc) out.drct(c.dof) = Ku(c.dof) - oobf(c.dof);
  return out;
  // END EXERCISE
}

}  // namespace ample
