//--------------------------------------------------------------------------
// solverChoice — the names of solver= and the ones this build has
//--------------------------------------------------------------------------
// The sparse solvers of Kt(fd,fd) (freeSystem.h, docs/scaling.md "The sparse
// solve"): LU, LDLT, KRYLOV and LDLT_HALVES in every build; LDLT_METIS with -DAMPLE_METIS=ON;
// CHOLMOD and UMFPACK with -DAMPLE_SUITESPARSE=ON; MUMPS with -DAMPLE_MUMPS=ON; PETSC with
// -DAMPLE_PETSC=ON
// (cmake/solverLibraries.cmake).
// Inputs:  a LinearSolver (mpData.h)
// Outputs: the names in the order of LinearSolver · the list this build has ·
//          InputError (exit 2) for a choice this build lacks, naming the
//          parameter, the choices built and the CMake option that adds it
// Tests:   tests/test_linSolve.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"
#include <string>
#include <vector>

namespace ample {

// the names of solver=, in the order of LinearSolver (a constant: reading it runs no code)
constexpr const char* solverNameList[] = {"LU",     "LDLT",        "LDLT_METIS", "CHOLMOD",
                                          "UMFPACK", "KRYLOV", "LDLT_HALVES", "MUMPS", "PETSC"};

const std::vector<std::string>& solverNames();  // solverNameList as strings
bool solverBuilt(LinearSolver choice);          // LU, LDLT: always; the others with their option
std::string solversBuilt();                     // e.g. "LU, LDLT"
void checkSolverBuilt(LinearSolver choice);     // InputError when not built

}  // namespace ample
