//--------------------------------------------------------------------------
// chosenSolve — linSolve with the solver= choice and the analysis kept
//--------------------------------------------------------------------------
// [AMPLE] eq 29. See chosenSolve.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "chosenSolve.h"
#include "ample/errors.h"
#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ample {

// Kt(fd,fd) symmetric to 1e-12 of its largest entry: each entry below the diagonal against
// its mirror (S.mirror: found once per pattern), or 0 without one, and each entry above the
// diagonal without a mirror against 0. A guard of cost only: the backward error below
// refuses the solve of an unsymmetric K too (LDL^T reads one triangle), after a wasted
// factorisation. The columns on the threads there are (the same answer on any number)
static bool symmetric(FreeSystem& S) {
  const SpMat& K = S.Kff;
  if (K.nonZeros() == 0) return true;
  const int *outer = K.outerIndexPtr(), *inner = K.innerIndexPtr();
  if (S.mirror.size() != size_t(K.nonZeros())) {        // a new pattern: K's transposed entries
    S.mirror.resize(K.nonZeros());
    for (int c = 0; c < K.outerSize(); ++c)
      for (int e = outer[c]; e < outer[c + 1]; ++e) {
        const int r = inner[e];
        const int* m = std::lower_bound(inner + outer[r], inner + outer[r + 1], c);
        S.mirror[e] = (m != inner + outer[r + 1] && *m == c) ? int(m - inner) : -1;
      }
  }
  const double tol = 1e-12 * K.coeffs().cwiseAbs().maxCoeff();
  const double* val = K.valuePtr();
  const int* mirror = S.mirror.data();
  long unequal = 0;
#ifdef _OPENMP
#pragma omp parallel for reduction(+ : unequal) schedule(static)
#endif
  for (int c = 0; c < K.outerSize(); ++c)
    for (int e = outer[c]; e < outer[c + 1]; ++e)
      if (inner[e] > c || (inner[e] < c && mirror[e] < 0))
        unequal += std::abs(val[e] - (mirror[e] >= 0 ? val[mirror[e]] : 0.0)) > tol;
  return unequal == 0;
}

// the residual r = K x - b (K x summed column by column, as Eigen's K * x: the same bits)
// and the backward error of x, ||r|| / (||K|| ||x|| + ||b||), in one pass over K
static double residualAndBackwardError(const SpMat& K, const Eigen::VectorXd& x, const Eigen::VectorXd& b,
                                       Eigen::VectorXd& r) {
  Eigen::VectorXd rowSum = Eigen::VectorXd::Zero(K.rows());
  r.setZero(K.rows());
  for (int k = 0; k < K.outerSize(); ++k)
    for (SpMat::InnerIterator it(K, k); it; ++it) {
      r(it.row()) += it.value() * x(k);
      rowSum(it.row()) += std::abs(it.value());
    }
  r -= b;
  return r.lpNorm<Eigen::Infinity>() /
         ((K.rows() ? rowSum.maxCoeff() : 0.0) * x.lpNorm<Eigen::Infinity>() + b.lpNorm<Eigen::Infinity>() + 1e-300);
}

double backwardError(const SpMat& K, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  Eigen::VectorXd r;
  return residualAndBackwardError(K, x, b, r);
}

// LDLT: Eigen's SimplicialLDLT factorises K (no pivoting) and solves; false when it fails or
// its backward error exceeds 1e-12 (a relative residual would refuse the ill-conditioned
// column of 2^14 cells: 1e-9..2e-8 there with a backward error of 1e-16); r: its residual
static bool ldltSolve(FreeSystem& S, const Eigen::VectorXd& rhs, Eigen::VectorXd& x, Eigen::VectorXd& r) {
  S.ldlt.factorize(S.Kff);
  S.factorisations++;
  if (S.ldlt.info() != Eigen::Success) return false;
  x = S.ldlt.solve(rhs);
  return x.allFinite() && residualAndBackwardError(S.Kff, x, rhs, r) <= 1e-12;  // (max norms skip NaN)
}

// SparseLU's numeric factorisation of S.Kff and the solve; RunError when it fails
static Eigen::VectorXd luSolve(FreeSystem& S, const Eigen::VectorXd& rhs) {
  if (!S.luAnalysed) S.lu.analyzePattern(S.Kff);        // once per pattern
  S.luAnalysed = true;
  S.lu.factorize(S.Kff);                                // numeric factorisation only
  S.factorisations++;
  if (S.lu.info() != Eigen::Success)
    throw RunError("SparseLU could not factorise the stiffness Kt(fd,fd) (" + S.lu.lastErrorMessage() +
                   "): the problem is singular, e.g. a rigid-body mode without enough boundary conditions "
                   "or a nearly empty cell", Failure::Singular);
  return S.lu.solve(rhs);
}

// solver=MUMPS and solver=PETSC (MUMPS by itself or over the MPI ranks): MUMPS's LDL^T where
// S.Kff is symmetric and the solve is accepted (as ldltSolve), else its LU; RunError when that
// fails too. factorSolve(symmetric, x): one factorisation and solve, false when it fails;
// message(): why it failed; r: the residual of an accepted LDL^T's solve, else left empty
template <class FactorSolve, class Message>
static Eigen::VectorXd mumpsSolve(FreeSystem& S, const Eigen::VectorXd& rhs, Eigen::VectorXd& r,
                                  FactorSolve factorSolve, Message message, const std::string& singular) {
  Eigen::VectorXd x;
  if (symmetric(S)) {
    S.factorisations++;
    if (factorSolve(true, x) && x.allFinite() && residualAndBackwardError(S.Kff, x, rhs, r) <= 1e-12) return x;
    r.resize(0);
    if (S.fallbacks++ == 0)                             // said at the run's end, as below
      S.notes += "ample: solver=" + solverNames()[size_t(S.choice)] +
                 ": MUMPS's LDL^T of Kt(fd,fd) failed or was inexact: its LU solves such passes\n";
  }
  S.factorisations++;
  if (!factorSolve(false, x)) throw RunError(message() + singular, Failure::Singular);
  return x;
}

// numeric factorisation of S.Kff and the solve: SparseLU (solver=LU), MUMPS, PETSC, or LDLT
// when Kff is symmetric and its solve succeeds (else SparseLU); RunError when LU fails.
// r: the residual S.Kff x - rhs where the acceptance computed it, else empty
static Eigen::VectorXd factorisedSolve(FreeSystem& S, const Eigen::VectorXd& rhs, Eigen::VectorXd& r) {
  const std::string singular = "): the problem is singular, e.g. a rigid-body mode without enough "
                               "boundary conditions or a nearly empty cell";
#ifdef AMPLE_HAVE_MUMPS
  if (S.choice == LinearSolver::MUMPS) {
    S.negativePivots = -1;
    const auto factorSolve = [&S, &rhs](bool symmetric, Eigen::VectorXd& x) {
      if (!S.mumps.factorize(S.Kff, symmetric)) return false;
      x = S.mumps.solve(rhs);
      if (symmetric) S.negativePivots = S.mumps.negativePivots();
      return true;
    };
    return mumpsSolve(S, rhs, r, factorSolve, [&S] { return S.mumps.message(); }, singular.substr(1));
  }
#endif
#ifdef AMPLE_HAVE_PETSC
  if (S.choice == LinearSolver::PETSC) {
    const auto factorSolve = [&S, &rhs](bool symmetric, Eigen::VectorXd& x) {
      return S.petsc.solve(S.Kff, rhs, x, symmetric);
    };
    return mumpsSolve(S, rhs, r, factorSolve, [&S] { return S.petsc.message(); }, singular.substr(1));
  }
#endif
  if (S.choice == LinearSolver::LDLT) {
    Eigen::VectorXd x;
    if (symmetric(S) && ldltSolve(S, rhs, x, r)) return x;
    r.resize(0);
    if (S.fallbacks++ == 0)                             // said at the run's end (ample: RunLog::notes)
      S.notes += "ample: solver=LDLT: Kt(fd,fd) not symmetric to 1e-12, or its factorisation failed "
                 "or was inexact: SparseLU solves such passes\n";
  }
  return luSolve(S, rhs);
}

LinSolveOut chosenSolve(FreeSystem& S, const std::vector<BC>& bc, const SpMat& Kt, const Eigen::VectorXd& oobf,
                        int NRit, const std::vector<int>& fd) {
  struct Chosen : FreeSolve {                            // linSolve's Kt(fd,fd) \ rhs by S's solver
    FreeSystem& S;
    explicit Chosen(FreeSystem& s) : S(s) {}
    Eigen::VectorXd solveFree(const SpMat& K, const std::vector<int>& f, const Eigen::VectorXd& rhs,
                              int pass) const override {
      return chosenSolveFree(S, K, f, rhs, pass);
    }
  };
  return linSolve(bc, Kt, oobf, NRit, fd, Chosen(S));
}

Eigen::VectorXd chosenSolveFree(FreeSystem& S, const SpMat& Kt, const std::vector<int>& fd, const Eigen::VectorXd& rhs,
                                int /*NRit*/) {
  refillFreeSystem(Kt, fd, S);                          // S.Kff = Kt(fd,fd), the pattern kept
  Eigen::VectorXd r;                                    // S.Kff x - rhs
  const Eigen::VectorXd x = factorisedSolve(S, rhs, r);
  if (r.size() == 0) r = S.Kff * x - rhs;               // (not computed by the acceptance)
  checkSolved(r, rhs);                                  // as solveFree: a singular Kt(fd,fd) refused
  return x;
}

}  // namespace ample
