//--------------------------------------------------------------------------
// freeSystem — Kt(fd,fd) of one load step, its pattern and its symbolic analysis
//--------------------------------------------------------------------------
// A fast part (see docs/structure.md, "The fast parts"). linSolve solves
// Kt(fd,fd) duvw(fd) = rhs ([AMPLE] eq 29) in every Newton-Raphson pass.
// Within a load step the free dofs fd and Kt's pattern do not change, so
//   buildFreeSystem  extracts the pattern of Kt(fd,fd) once, remembers where
//                    each of its values sits in Kt (fromKt) and runs the
//                    chosen solver's symbolic analysis (its ordering) once;
//   refillFreeSystem copies Kt's values into it for each pass, and chosenSolve
//                    only refactorises numerically.
// The main loop keeps one FreeSystem for the whole run: a load step whose fd
// and Kt(fd,fd) pattern (Kt's free entries compared with fromKt entry by
// entry, O(nnz)) are those of the step before (no point entered or left a
// cell) keeps the analysis too.
// choice (setup parameter solver=, docs/solvers.md):
//   LU          Eigen's SparseLU, COLAMD ordering (the default; measured
//               against AMD and METIS in docs/scaling.md: the least fill)
//   LDLT        Eigen's SimplicialLDLT, AMD ordering, used in every pass whose
//               Kt(fd,fd) is symmetric to 1e-12, else SparseLU
//   MUMPS       MUMPS's LDL^T (general symmetric: indefinite too) where Kt(fd,fd)
//               is symmetric and its solve is accepted, else MUMPS's LU
//               (mumps.h; AMPLE_MUMPS); the negative pivots of the LDL^T kept
//   PETSC       MUMPS over the MPI ranks of `mpirun -n N` (petscSolve.h;
//               AMPLE_PETSC), PETSc's linear solver server: as MUMPS, its
//               LDL^T where symmetric and accepted, else its LU
// LDLT on a pass that is not symmetric (or whose factorisation fails, or whose
// solve has a backward error above 1e-12: chosenSolve.cpp) falls back to
// SparseLU for that pass, said once (notes: ample prints it on stderr at the
// run's end; fallbacks counts);
// SparseLU is analysed when first needed.
// What it saves: the extraction and the ordering in every pass (see the
// closing figures in docs/structure.md).
// Inputs:  Kt (nDoF x nDoF, compressed, rows sorted in each column: as stiffnessPattern
//          builds it) · fd (nfd free dofs, ascending: as detFDoFs gives them) · S.choice
// Outputs: S (FreeSystem): fd, pattern, fromKt, Kff (nfd x nfd), the chosen solver analysed
// Tests:   tests/test_linSolve.cpp
//--------------------------------------------------------------------------
#pragma once
#include "solverChoice.h"
#include "stiffnessPattern.h"
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <string>
#include <vector>
#ifdef AMPLE_HAVE_MUMPS
#include "mumps.h"
#endif
#ifdef AMPLE_HAVE_PETSC
#include "petscSolve.h"
#endif

namespace ample {

struct FreeSystem {
  LinearSolver choice = LinearSolver::LU;      // solver= (above)
  std::vector<int> fd;                         // free dofs it was built for
  int ktRows = 0;                              // rows of the Kt it was built for
  std::vector<int> fromKt;                     // Kff value e is Kt value fromKt[e]
  std::vector<int> mirror;                     // Kff value e's transposed entry, or -1 (chosenSolve's)
  SpMat Kff;                                   // Kt(fd,fd)
  Eigen::SparseLU<SpMat, Eigen::COLAMDOrdering<int>> lu;  // LU, and LDLT's fallback
  bool luAnalysed = false;                     // lu's analysis is of this pattern
  Eigen::SimplicialLDLT<SpMat> ldlt;           // LDLT (AMD ordering)
#ifdef AMPLE_HAVE_MUMPS
  MumpsSolver mumps;                           // MUMPS
#endif
#ifdef AMPLE_HAVE_PETSC
  PetscSolver petsc;                           // PETSC
#endif
  int negativePivots = -1;                     // MUMPS: of the last LDL^T (-1: none, or an LU)
  int builds = 0, fallbacks = 0;               // analyses run; symmetric passes solved by an LU
  std::string notes;                           // lines for stderr (the first LU fallback), taken
                                               // by the run's log (program/run.cpp recordStep)
  long factorisations = 0;                     // numeric factorisations (summary.json)
};

// S.Kff = Kt(fd,fd) and S.fromKt, no analysis (buildFreeSystem's first half; the benchmark's)
void extractFreeSystem(const SpMat& Kt, const std::vector<int>& fd, FreeSystem& S);
void buildFreeSystem(const SpMat& Kt, const std::vector<int>& fd, FreeSystem& S);
// Kt(fd,fd) with the values of Kt; builds S first when fd or Kt's pattern changed
void refillFreeSystem(const SpMat& Kt, const std::vector<int>& fd, FreeSystem& S);

}  // namespace ample
