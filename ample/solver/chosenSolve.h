//--------------------------------------------------------------------------
// chosenSolve — linSolve with the solver= choice and the analysis kept
//--------------------------------------------------------------------------
// [AMPLE] eq 29: linSolve (ample/linSolve.h) with its solveFree replaced by
// chosenSolveFree: the same refusal of a singular Kt(fd,fd). Kt(fd,fd) is solved with the solver chosen
// by solver= (S.choice, freeSystem.h: SparseLU, LDLT, MUMPS, PETSC), and its pattern and
// symbolic analysis are kept in S while fd and Kt's pattern stay the same
// (SparseLU: the same factors as linSolve's, bit for bit). The program uses
// it for every solver but SparseLU, and for SparseLU on large runs.
// The acceptance of a symmetric factorisation's solve (LDLT, MUMPS, PETSC):
// its normwise backward error ||K x - b|| / (||K|| ||x|| + ||b||), infinity
// norms, at most 1e-12 (the relative change of K and b that x solves exactly;
// round-off gives ~1e-16 whatever the condition of K, an unstable
// factorisation much more).
// Inputs:  S · bc (nbc) · Kt (nDoF x nDoF) · oobf (nDoF) · NRit · fd (nfd)
// Outputs: duvw (nDoF) · drct (nDoF) · S (its counters, notes) · backwardError
// Tests:   tests/test_linSolve.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/linSolve.h"
#include "freeSystem.h"

namespace ample {

// linSolve with chosenSolveFree
LinSolveOut chosenSolve(FreeSystem& S, const std::vector<BC>& bc, const SpMat& Kt, const Eigen::VectorXd& oobf,
                        int NRit, const std::vector<int>& fd);
// solveFree's work by the chosen solver, the pattern and analysis kept in S (NRit unused, as solveFree's)
Eigen::VectorXd chosenSolveFree(FreeSystem& S, const SpMat& Kt, const std::vector<int>& fd, const Eigen::VectorXd& rhs,
                                int NRit);

// the normwise backward error of x for K x = b: ||K x - b||_inf / (||K||_inf ||x||_inf + ||b||_inf)
double backwardError(const SpMat& K, const Eigen::VectorXd& x, const Eigen::VectorXd& b);

}  // namespace ample
