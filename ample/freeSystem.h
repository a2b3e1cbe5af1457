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
// What it saves: the extraction and the ordering in every pass (see the
// closing figures in docs/structure.md).
// Inputs:  Kt (nDoF x nDoF) · fd (nfd free dofs, ascending)
// Outputs: S (FreeSystem): fd, fromKt, Kff (nfd x nfd), solver analysed
// Tests:   tests/test_linSolve.cpp
//--------------------------------------------------------------------------
#pragma once
#include "stiffnessPattern.h"
#include <Eigen/SparseLU>
#include <vector>

namespace ample {

struct FreeSystem {
  std::vector<int> fd;       // free dofs it was built for
  long ktNonZeros = -1;      // size of the Kt pattern it was built for
  std::vector<int> fromKt;   // Kff value e is Kt value fromKt[e]
  SpMat Kff;                 // Kt(fd,fd)
  Eigen::SparseLU<SpMat, Eigen::COLAMDOrdering<int>> solver;
};

void buildFreeSystem(const SpMat& Kt, const std::vector<int>& fd, FreeSystem& S);
// Kt(fd,fd) with the values of Kt; builds S first when fd or Kt's pattern changed
void refillFreeSystem(const SpMat& Kt, const std::vector<int>& fd, FreeSystem& S);

}  // namespace ample
