//--------------------------------------------------------------------------
// solverChoice — the names of solver= and the ones this build has
//--------------------------------------------------------------------------
// The sparse solvers of Kt(fd,fd) (freeSystem.h, docs/solvers.md): LU and
// LDLT in every build; MUMPS with -DAMPLE_MUMPS=ON; PETSC with -DAMPLE_PETSC=ON
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
constexpr const char* solverNameList[] = {"LU", "LDLT", "MUMPS", "PETSC"};

const std::vector<std::string>& solverNames();  // solverNameList as strings
bool solverBuilt(LinearSolver choice);          // LU, LDLT: always; the others with their option
std::string solversBuilt();                     // e.g. "LU, LDLT"
void checkSolverBuilt(LinearSolver choice);     // InputError when not built

}  // namespace ample
