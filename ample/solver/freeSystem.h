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
// choice (setup parameter solver=, docs/scaling.md "The sparse solve"):
//   LU          Eigen's SparseLU, COLAMD ordering (the default; measured
//               against AMD and METIS in docs/scaling.md: the least fill)
//   LDLT        Eigen's SimplicialLDLT, AMD ordering          } used in every pass whose
//   LDLT_METIS  the same with METIS (built with AMPLE_METIS)  } Kt(fd,fd) is symmetric
//   CHOLMOD     CHOLMOD supernodal LL^T (AMPLE_SUITESPARSE)   } to 1e-12, else SparseLU
//   UMFPACK     UMFPACK's LU (AMPLE_SUITESPARSE)
//   KRYLOV      one numeric factorisation a load step (at NRit == 1: LDLT
//               when Kt(fd,fd) is symmetric, else SparseLU); the later passes
//               of the step by PCG (symmetric) or restarted GMRES (krylov.h)
//               preconditioned with it, to a backward error of 1e-14; a pass
//               whose Krylov solve needs more than krylovMaxIt iterations,
//               misses 1e-12, or leaves a residual over 1e-3 of the right-hand
//               side (Kt nearly singular) refactorises and solves directly, and its factor
//               preconditions the passes after it; so does a pass after one
//               whose Krylov solve needed more than krylovMaxIt / 2 (the factor
//               has drifted: the next solve would cost about a factorisation)
//   LDLT_HALVES LDL^T of two halves of the free dofs and the interface between
//               them (halvesLDLT.h): the halves factorised on two threads at
//               once; symmetric passes only, as LDLT
//   MUMPS       MUMPS's LDL^T (general symmetric: indefinite too) where Kt(fd,fd)
//               is symmetric and its solve is accepted, else MUMPS's LU
//               (mumps.h; AMPLE_MUMPS); the negative pivots of the LDL^T kept
//   PETSC       MUMPS over the MPI ranks of `mpirun -n N` (petscSolve.h;
//               AMPLE_PETSC), PETSc's linear solver server: as MUMPS, its
//               LDL^T where symmetric and accepted, else its LU
// A symmetric choice whose pass is not symmetric (or whose factorisation
// fails, e.g. LL^T of an indefinite Kt, or whose solve has a backward error
// above 1e-12: linSolve.cpp) falls back to SparseLU for that pass,
// said once (notes: ample prints it on stderr at the run's end; fallbacks counts);
// SparseLU is analysed when first needed.
// What it saves: the extraction and the ordering in every pass (see the
// closing figures in docs/structure.md).
// Inputs:  Kt (nDoF x nDoF, compressed, rows sorted in each column: as stiffnessPattern
//          builds it) · fd (nfd free dofs, ascending: as detFDoFs gives them) · S.choice
// Outputs: S (FreeSystem): fd, pattern, fromKt, Kff (nfd x nfd), the chosen solver analysed
// Tests:   tests/test_linSolve.cpp
//--------------------------------------------------------------------------
#pragma once
#include "halvesLDLT.h"
#include "solverChoice.h"
#include "stiffnessPattern.h"
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <string>
#include <vector>
#ifdef AMPLE_HAVE_METIS
#include <iostream>  // Eigen/MetisSupport uses std::cerr without including it
#include <Eigen/MetisSupport>
#endif
#ifdef AMPLE_HAVE_SUITESPARSE
#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>
#endif
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
  SpMat Kff;                                   // Kt(fd,fd)
  Eigen::SparseLU<SpMat, Eigen::COLAMDOrdering<int>> lu;  // LU, and the symmetric choices' fallback
  bool luAnalysed = false;                     // lu's analysis is of this pattern
  Eigen::SimplicialLDLT<SpMat> ldlt;           // LDLT (AMD ordering)
  HalvesLDLT halves;                           // LDLT_HALVES
  const Eigen::Matrix<double, Eigen::Dynamic, nD, Eigen::RowMajor>* nodeCoord = nullptr;  // LDLT_HALVES
                                               // cuts the free dofs in two where their nodes are
#ifdef AMPLE_HAVE_METIS
  Eigen::SimplicialLDLT<SpMat, Eigen::Lower, Eigen::MetisOrdering<int>> ldltMetis;  // LDLT_METIS
#endif
#ifdef AMPLE_HAVE_SUITESPARSE
  Eigen::CholmodSupernodalLLT<SpMat> cholmod;  // CHOLMOD
  Eigen::UmfPackLU<SpMat> umfpack;             // UMFPACK
#endif
#ifdef AMPLE_HAVE_MUMPS
  MumpsSolver mumps;                           // MUMPS
#endif
#ifdef AMPLE_HAVE_PETSC
  PetscSolver petsc;                           // PETSC
#endif
  int negativePivots = -1;                     // MUMPS: of the last LDL^T (-1: none, or an LU)
  int builds = 0, fallbacks = 0;               // analyses run; symmetric passes solved by LU
  std::string notes;                           // lines for stderr (the first LU fallback), taken
                                               // by the run's log (program/run.cpp recordStep)
  bool factorHeld = false;                     // KRYLOV: ldlt or lu holds a factor of this step
  bool factorSymmetric = false;                // KRYLOV: that factor is ldlt's (Kff was symmetric)
  int krylovMaxIt = 30;                        // KRYLOV: iterations before it refactorises
  int krylovLastIterations = 0;                // KRYLOV: of the last Krylov solve with this factor
  long factorisations = 0;                     // numeric factorisations (summary.json)
  long krylovSolves = 0, krylovIterations = 0; // KRYLOV: Krylov solves tried, iterations spent
};

// S.Kff = Kt(fd,fd) and S.fromKt, no analysis (buildFreeSystem's first half; the benchmark's)
void extractFreeSystem(const SpMat& Kt, const std::vector<int>& fd, FreeSystem& S);
void buildFreeSystem(const SpMat& Kt, const std::vector<int>& fd, FreeSystem& S);
// Kt(fd,fd) with the values of Kt; builds S first when fd or Kt's pattern changed
void refillFreeSystem(const SpMat& Kt, const std::vector<int>& fd, FreeSystem& S);

}  // namespace ample
