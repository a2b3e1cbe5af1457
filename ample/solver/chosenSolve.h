//--------------------------------------------------------------------------
// chosenSolve — linSolve with the solver= choice and the analysis kept
//--------------------------------------------------------------------------
// [AMPLE] eq 29: linSolve (ample/linSolve.h) with its solveFree replaced by
// chosenSolveFree: the same refusal of a singular Kt(fd,fd). Kt(fd,fd) is solved with the solver chosen
// by solver= (S.choice, freeSystem.h: SparseLU, LDLT, ...), and its pattern and
// symbolic analysis are kept in S while fd and Kt's pattern stay the same
// (SparseLU: the same factors as linSolve's, bit for bit). The program uses
// it for every solver but SparseLU, and for SparseLU on large runs.
// Inputs:  S · bc (nbc) · Kt (nDoF x nDoF) · oobf (nDoF) · NRit · fd (nfd)
// Outputs: duvw (nDoF) · drct (nDoF) · S (its counters, notes)
// Tests:   tests/test_linSolve.cpp, tests/test_krylov.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/linSolve.h"
#include "freeSystem.h"

namespace ample {

// linSolve with chosenSolveFree
LinSolveOut chosenSolve(FreeSystem& S, const std::vector<BC>& bc, const SpMat& Kt, const Eigen::VectorXd& oobf,
                        int NRit, const std::vector<int>& fd);
// solveFree's work by the chosen solver, the pattern and analysis kept in S
Eigen::VectorXd chosenSolveFree(FreeSystem& S, const SpMat& Kt, const std::vector<int>& fd, const Eigen::VectorXd& rhs,
                                int NRit);

}  // namespace ample
