//--------------------------------------------------------------------------
// freeSystem — Kt(fd,fd) of one load step, its pattern and its symbolic analysis
//--------------------------------------------------------------------------
// A fast part (see docs/structure.md, "The fast parts"). linSolve solves
// Kt(fd,fd) duvw(fd) = rhs (seed 002 eq 29) in every Newton-Raphson pass.
// Within a load step the free dofs fd and Kt's pattern do not change, so
//   buildFreeSystem  extracts the pattern of Kt(fd,fd) once, remembers where
//                    each of its values sits in Kt (fromKt) and runs
//                    SparseLU's symbolic analysis (COLAMD ordering) once;
//   refillFreeSystem copies Kt's values into it for each pass, and linSolve
//                    only refactorises numerically.
// The main loop keeps one FreeSystem for the whole run: a load step whose fd
// and Kt pattern (compared entry by entry, O(nnz)) are those of the step
// before (no point entered or left a cell) keeps the analysis too.
// choice = LDLT (setup parameter solver=LDLT, beyond the design card):
// Eigen's SimplicialLDLT (AMD ordering) is analysed as well and used in every
// pass whose Kt(fd,fd) is symmetric to 1e-12 of its largest entry; a pass
// that is not falls back to SparseLU, said once on stderr (fallbacks counts).
// What it saves: the extraction and the ordering in every pass (see the
// closing figures in docs/structure.md).
// Inputs:  Kt (nDoF x nDoF) · fd (nfd free dofs, ascending) · S.choice
// Outputs: S (FreeSystem): fd, pattern, fromKt, Kff (nfd x nfd), lu (and ldlt) analysed
// Tests:   tests/test_linSolve.cpp
//--------------------------------------------------------------------------
#pragma once
#include "stiffnessPattern.h"
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <vector>

namespace ample {

struct FreeSystem {
  LinearSolver choice = LinearSolver::LU;      // LU (default) or LDLT when symmetric
  std::vector<int> fd;                         // free dofs it was built for
  std::vector<int> ktOuter, ktInner;           // the Kt pattern it was built for
  std::vector<int> fromKt;                     // Kff value e is Kt value fromKt[e]
  SpMat Kff;                                   // Kt(fd,fd)
  Eigen::SparseLU<SpMat, Eigen::COLAMDOrdering<int>> lu;
  Eigen::SimplicialLDLT<SpMat> ldlt;           // analysed only for choice = LDLT
  int builds = 0, fallbacks = 0;               // analyses run; LDLT passes solved by LU
};

void buildFreeSystem(const SpMat& Kt, const std::vector<int>& fd, FreeSystem& S);
// Kt(fd,fd) with the values of Kt; builds S first when fd or Kt's pattern changed
void refillFreeSystem(const SpMat& Kt, const std::vector<int>& fd, FreeSystem& S);

}  // namespace ample
