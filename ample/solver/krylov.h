//--------------------------------------------------------------------------
// krylov — preconditioned conjugate gradients and right-preconditioned GMRES
//--------------------------------------------------------------------------
// solver=KRYLOV (freeSystem.h, linSolve.cpp) factorises Kt(fd,fd) once per
// load step ([AMPLE] eq 29 at NRit == 1) and solves the later Newton passes
// of the step by a Krylov method preconditioned with that factor M ~ K:
//   pcg    K symmetric and M the factor of a symmetric matrix (LDL^T)
//   gmres  otherwise; right preconditioned, K M^-1 u = b, x = M^-1 u, so its
//          residual b - K x is the true one; restarted every `restart` steps
// Both start from x = 0 and stop when the normwise backward error
//   ||b - K x||_inf / (||K||_inf ||x||_inf + ||b||_inf)
// is at most `target` (1e-14 in linSolve: below the acceptance 1e-12 of a
// direct solve, so the Newton passes match it closely), or has stagnated
// below `accept` (1e-12), or after maxIt iterations. converged says whether
// the true backward error of the returned x is at most `accept`.
// Inputs:  K (n x n) · M (r -> M^-1 r) · b (n) · maxIt · target · accept
// Outputs: x (n) · KrylovResult: converged, iterations, backwardError
// Tests:   tests/test_linSolve.cpp
//--------------------------------------------------------------------------
#pragma once
#include "stiffnessPattern.h"
#include <functional>

namespace ample {

using Preconditioner = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;  // r -> M^-1 r

struct KrylovResult {
  bool converged = false;     // true backward error <= accept
  int iterations = 0;         // products K z (one per iteration)
  double backwardError = 1.0; // of the returned x, from its true residual
};

double infNorm(const SpMat& K);  // ||K||_inf, the largest row sum of |K|
// ||K x - b||_inf / (normK ||x||_inf + ||b||_inf), normK = infNorm(K)
double backwardError(const SpMat& K, double normK, const Eigen::VectorXd& x, const Eigen::VectorXd& b);

KrylovResult pcg(const SpMat& K, const Preconditioner& M, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                 int maxIt, double target = 1e-14, double accept = 1e-12);
KrylovResult gmres(const SpMat& K, const Preconditioner& M, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                   int maxIt, double target = 1e-14, double accept = 1e-12, int restart = 10);

}  // namespace ample
