//--------------------------------------------------------------------------
// linSolve — linear solve for the displacement and reaction increments
//--------------------------------------------------------------------------
// [AMPLE] eq 29. Skipped at NRit == 0 (that pass only builds Kt); the
// prescribed displacement increments enter at NRit == 1 and are zero after:
//   duvw(bc) = prescribed, duvw(fd) = Kt(fd,fd) \ (oobf(fd) - Kt(fd,bc) duvw(bc)),
//   drct(bc) = Kt(bc,:) duvw - oobf(bc).
// Solved with Eigen's SparseLU (COLAMD ordering) or the solver chosen by
// solver= (freeSystem.h); a singular or failed factorisation throws RunError
// naming the cause. With a cache (FreeSystem,
// a fast part: freeSystem.h) the pattern of Kt(fd,fd) and the symbolic
// analysis are reused while fd and Kt's pattern stay the same.
// Inputs:  bc (nbc) · Kt (nDoF x nDoF) · oobf (nDoF) · NRit · fd (nfd) · cache (optional)
// Outputs: duvw (nDoF) · drct (nDoF)
// Tests:   tests/test_linSolve.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/solver/freeSystem.h"
#include "mpData.h"

namespace ample {

struct LinSolveOut {
  Eigen::VectorXd duvw;  // iterative nodal displacement increment
  Eigen::VectorXd drct;  // iterative reaction force increment
};

LinSolveOut linSolve(const std::vector<BC>& bc, const SpMat& Kt, const Eigen::VectorXd& oobf,
                     int NRit, const std::vector<int>& fd, FreeSystem* cache = nullptr);

}  // namespace ample
