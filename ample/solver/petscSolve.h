//--------------------------------------------------------------------------
// petscSolve — Kt(fd,fd) x = rhs by PETSc over MPI ranks (solver=PETSC, -DAMPLE_PETSC=ON)
//--------------------------------------------------------------------------
// `mpirun -n N ample SETUP solver=PETSC ...`: rank 0 runs the program, the
// point loop on its threads; ranks 1 .. N-1 wait in PETSc's MPI linear solver
// server (PCMPI, PETSc 3.18: petscStart, the first thing main does) and join
// each solve: rank 0's Kt(fd,fd), a sequential AIJ matrix, goes to them as a
// parallel one and MUMPS factorises it over the ranks: its LDL^T where Kt(fd,fd)
// is symmetric (the KSP of prefix "sym_": -sym_mpi_pc_type cholesky, MUMPS's
// general symmetric mode), else its LU (-mpi_ksp_type preonly -mpi_pc_type lu
// -mpi_pc_factor_mat_solver_type mumps). PCMPI uses at most one rank per 2,000 rows (-pc_mpi_minimum_count_per_rank;
// PETSC_OPTIONS overrides any of these). Without mpirun, one process: PETSc
// starts at the first solve and MUMPS runs there alone. newPattern: Kt's pattern
// changed (the matrix is built again); the values are copied every pass.
// Inputs:  Kff (nfd x nfd, compressed) · rhs (nfd)
// Outputs: x (nfd) · false and message() where the solve fails (a singular Kff)
// Tests:   tests/test_linSolve.cpp (every solver= of the build); tests/petsc_ranks.py (two MPI ranks)
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"
#include <memory>
#include <string>

namespace ample {

// PetscInitialize with the server's options when started by an MPI launcher (ranks
// other than 0 then serve solves and exit inside it); otherwise nothing yet
void petscStart();
// PetscFinalize if PETSc was started (the server's ranks are released)
void petscEnd();

class PetscSolver {
 public:
  PetscSolver();
  ~PetscSolver();
  PetscSolver(const PetscSolver&);              // a copy starts without a matrix
  PetscSolver& operator=(const PetscSolver&);
  void newPattern();
  // symmetric: MUMPS's LDL^T (the lower triangle read), else its LU
  bool solve(const SpMat& Kff, const Eigen::VectorXd& rhs, Eigen::VectorXd& x, bool symmetric);
  const std::string& message() const { return message_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> p_;
  std::string message_;
};

}  // namespace ample
