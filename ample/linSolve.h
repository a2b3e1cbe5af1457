//--------------------------------------------------------------------------
// linSolve — linear solve for the displacement and reaction increments
//--------------------------------------------------------------------------
// [AMPLE] eq 29. Skipped at NRit == 0 (that pass only builds Kt); the
// prescribed displacement increments enter at NRit == 1 and are zero after:
//   duvw(bc) = prescribed, duvw(fd) = Kt(fd,fd) \ (oobf(fd) - Kt(fd,bc) duvw(bc)),
//   drct(bc) = Kt(bc,:) duvw - oobf(bc).
// Kt(fd,fd) x = rhs is solved by solveFree: Eigen's SparseLU (COLAMD ordering),
// or another solver (ample/solver/chosenSolve.h); a singular Kt(fd,fd) throws
// RunError (Failure::Singular).
// Inputs:  bc (nbc) · Kt (nDoF x nDoF) · oobf (nDoF) · NRit · fd (nfd) · [solve]
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

// x with Kt(fd,fd) x = rhs, by SparseLU; RunError when Kt(fd,fd) is singular
Eigen::VectorXd solveFree(const SpMat& Kt, const std::vector<int>& fd, const Eigen::VectorXd& rhs, int NRit);
// RunError (Failure::Singular) when the residual Kff x - rhs is above 1e-3 of rhs: a zero pivot
void checkSolved(const Eigen::VectorXd& residual, const Eigen::VectorXd& rhs);
// Kt(fd,fd) \ rhs: solveFree (SparseLU) here; the program's hooks (hooks.h) choose another solver
struct FreeSolve {
  virtual Eigen::VectorXd solveFree(const SpMat& Kt, const std::vector<int>& fd, const Eigen::VectorXd& rhs,
                                    int NRit) const {
    return ample::solveFree(Kt, fd, rhs, NRit);
  }
};

LinSolveOut linSolve(const std::vector<BC>& bc, const SpMat& Kt, const Eigen::VectorXd& oobf,
                     int NRit, const std::vector<int>& fd, const FreeSolve& solver = FreeSolve());

}  // namespace ample
