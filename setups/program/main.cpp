//--------------------------------------------------------------------------
// main — entry point of the `ample` program
//--------------------------------------------------------------------------
// Reads the command line (cli.h), then runs the setup (run.h): program.cpp.
//   ample --list
//   ample compaction nelsy=128 mpType=1 --vtk 0
//   ample collapse a=2 mp=3 --out results/collapse_h1
// Exit status: 0 converged, 1 a load step did not converge or the run could
// not go on, 2 bad input, 3 the student copy reached an exercise not done
// (one line "ample: needs exercise X: see docs/exercises.md#X").
//--------------------------------------------------------------------------
#include "program.h"
#ifdef AMPLE_HAVE_PETSC
#include "ample/solver/petscSolve.h"
#endif

int main(int argc, char** argv) {
#ifdef AMPLE_HAVE_PETSC
  ample::petscStart();      // under mpirun: ranks 1.. serve solver=PETSC's solves and end there
  struct PetscEnd { ~PetscEnd() { ample::petscEnd(); } } end;
#endif
  return ample::program(std::vector<std::string>(argv + 1, argv + argc));
}
