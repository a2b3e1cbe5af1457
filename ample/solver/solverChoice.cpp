//--------------------------------------------------------------------------
// solverChoice — the names of solver= and the ones this build has
//--------------------------------------------------------------------------
// See solverChoice.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "solverChoice.h"
#include "ample/errors.h"
#include <iterator>

namespace ample {

static_assert(std::size(solverNameList) == size_t(LinearSolver::PETSC) + 1, "a name for each LinearSolver");

const std::vector<std::string>& solverNames() {
  static const std::vector<std::string> names(std::begin(solverNameList), std::end(solverNameList));
  return names;
}

// the CMake option that builds a choice ("" for the ones every build has)
static std::string optionFor(LinearSolver choice) {
  if (choice == LinearSolver::MUMPS) return "AMPLE_MUMPS";
  if (choice == LinearSolver::PETSC) return "AMPLE_PETSC";
  return "";
}

bool solverBuilt(LinearSolver choice) {
  const std::string option = optionFor(choice);
#ifdef AMPLE_HAVE_MUMPS
  if (option == "AMPLE_MUMPS") return true;
#endif
#ifdef AMPLE_HAVE_PETSC
  if (option == "AMPLE_PETSC") return true;
#endif
  return option.empty();
}

std::string solversBuilt() {
  std::string list;
  for (size_t k = 0; k < solverNames().size(); ++k)
    if (solverBuilt(LinearSolver(k))) list += (list.empty() ? "" : ", ") + solverNames()[k];
  return list;
}

void checkSolverBuilt(LinearSolver choice) {
  const size_t k = size_t(choice);
  if (k >= solverNames().size())
    throw InputError("solver=" + std::to_string(k) + ": no such sparse solver; this build has " + solversBuilt());
  if (solverBuilt(choice)) return;
  const std::string library = optionFor(choice) == "AMPLE_MUMPS" ? "libmumps-seq-dev" : "petsc-dev";
  throw InputError("solver=" + solverNames()[k] + " is not in this build: it has solver=" + solversBuilt() +
                   "; to add " + solverNames()[k] + ", configure with -D" + optionFor(choice) +
                   "=ON (needs " + library + ") and rebuild");
}

}  // namespace ample
