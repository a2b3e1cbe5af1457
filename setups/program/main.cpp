//--------------------------------------------------------------------------
// main — entry point of the `ample` program
//--------------------------------------------------------------------------
// Reads the command line (cli.h), then runs the setup (ample.h).
//   ample --list
//   ample compaction nelsy=128 mpType=1 --vtk 0
//   ample collapse a=2 mp=3 --out results/collapse_h1
// Exit status: 0 converged, 1 a load step did not converge or the run could
// not go on, 2 bad input, 3 the student copy reached an exercise not done
// (one line "ample: needs exercise X: see docs/exercises.md#X").
//--------------------------------------------------------------------------
#include "cli.h"
#include "ample/errors.h"
#ifdef AMPLE_HAVE_PETSC
#include "ample/solver/petscSolve.h"
#endif
#include <iostream>

int main(int argc, char** argv) {
  using namespace ample;
#ifdef AMPLE_HAVE_PETSC
  petscStart();             // under mpirun: ranks 1.. serve solver=PETSC's solves and end there
  struct PetscEnd { ~PetscEnd() { petscEnd(); } } end;
#endif
  CliRequest req;
  try {
    req = parseArgs(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const InputError& e) {
    std::cerr << "ample: " << e.what() << "\n";
    return 2;
  }
  switch (req.mode) {
    case CliMode::List: std::cout << listText(); return 0;
    case CliMode::Help: std::cout << usageText() << "setups:\n" << listText(); return 0;
    case CliMode::SetupHelp: std::cout << setupHelpText(*req.setup); return 0;
    case CliMode::Run: break;
  }
  try {
    return ample::ample(*req.setup, req.params, req.options);
  } catch (const ExerciseNotDone& e) {  // the student copy (docs/exercises.md)
    std::cerr << "ample: needs exercise " << e.what() << "\n";
    return 3;
  } catch (const InputError& e) {      // the setup's problem is inconsistent, or --out
    std::cerr << "ample: " << e.what() << "\n";   // cannot be made (before any file is written)
    return 2;
  } catch (const std::exception& e) {  // e.g. a result file cannot be written at the end
    std::cerr << "ample: " << e.what() << "\n";
    return 1;
  }
}
