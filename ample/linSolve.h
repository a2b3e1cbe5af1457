//--------------------------------------------------------------------------
// linSolve — linear solve for the displacement and reaction increments
//--------------------------------------------------------------------------
// Seed 002 eq 29. Skipped at NRit == 0 (that pass only builds Kt); the
// prescribed displacement increments enter at NRit == 1 and are zero after:
//   duvw(bc) = prescribed, duvw(fd) = Kt(fd,fd) \ (oobf(fd) - Kt(fd,bc) duvw(bc)),
//   drct(bc) = Kt(bc,:) duvw - oobf(bc).
// Solved with Eigen's SparseLU (COLAMD ordering); a singular or failed
// factorisation throws RunError naming the cause. With a cache (FreeSystem)
// the symbolic analysis is reused while fd and Kt's pattern stay the same.
// Inputs:  bc (nbc) · Kt (nDoF x nDoF) · oobf (nDoF) · NRit · fd (nfd) · cache (optional)
// Outputs: duvw (nDoF) · drct (nDoF)
// Tests:   tests/test_linSolve.cpp
//--------------------------------------------------------------------------
#pragma once
#include "mpData.h"
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

namespace ample {

using SpMat = Eigen::SparseMatrix<double>;

struct LinSolveOut {
  Eigen::VectorXd duvw;  // iterative nodal displacement increment
  Eigen::VectorXd drct;  // iterative reaction force increment
};

// the free-dof system Kt(fd,fd) of one load step: its pattern, where its values
// sit in Kt, and SparseLU's symbolic analysis — all fixed while fd and Kt's
// pattern are, so the main loop keeps one per load step and only refactorises
struct FreeSystem {
  std::vector<int> fd;       // free dofs it was built for
  long ktNonZeros = -1;      // size of the Kt pattern it was built for
  std::vector<int> fromKt;   // Kff value e is Kt value fromKt[e]
  SpMat Kff;
  Eigen::SparseLU<SpMat, Eigen::COLAMDOrdering<int>> solver;
};
void buildFreeSystem(const SpMat& Kt, const std::vector<int>& fd, FreeSystem& S);

LinSolveOut linSolve(const std::vector<BC>& bc, const SpMat& Kt, const Eigen::VectorXd& oobf,
                     int NRit, const std::vector<int>& fd, FreeSystem* cache = nullptr);

}  // namespace ample
