//--------------------------------------------------------------------------
// linSolve — linear solve for the displacement and reaction increments
//--------------------------------------------------------------------------
// [AMPLE] eq 29. Skipped at NRit == 0 (that pass only builds Kt); the
// prescribed displacement increments enter at NRit == 1 and are zero after:
//   duvw(bc) = prescribed, duvw(fd) = Kt(fd,fd) \ (oobf(fd) - Kt(fd,bc) duvw(bc)),
//   drct(bc) = Kt(bc,:) duvw - oobf(bc).
// Solved with Eigen's SparseLU (COLAMD ordering); a singular Kt(fd,fd) throws
// RunError (Failure::Singular).
// Inputs:  bc (nbc) · Kt (nDoF x nDoF) · oobf (nDoF) · NRit · fd (nfd)
// Outputs: duvw (nDoF) · drct (nDoF)
// Tests:   tests/test_linSolve.cpp
//--------------------------------------------------------------------------
#pragma once
#include "mpData.h"

namespace ample {

struct LinSolveOut {
  Eigen::VectorXd duvw;  // iterative nodal displacement increment
  Eigen::VectorXd drct;  // iterative reaction force increment
};

LinSolveOut linSolve(const std::vector<BC>& bc, const SpMat& Kt, const Eigen::VectorXd& oobf,
                     int NRit, const std::vector<int>& fd);

}  // namespace ample
