//--------------------------------------------------------------------------
// errors.h — the two kinds of failure the program reports
//--------------------------------------------------------------------------
// InputError: bad input (unknown setup or parameter, value out of range);
//   the program exits with status 2 before any work is done.
// RunError: the analysis cannot go on (a load step did not converge, a point
//   left the grid, the stiffness is singular); the program exits with status 1
//   and keeps the output of the last converged load step.
// ExerciseNotDone (exercise.h): a blanked region of the student copy was reached.
//--------------------------------------------------------------------------
#pragma once
#include "constitutive/exercise.h"  // ExerciseNotDone: a blanked exercise of the student copy
#include <stdexcept>
#include <string>

namespace ample {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// what stopped a run, so that the message can say what to try (whatToTry, loadSteps.h)
enum class Failure {
  Other,          // named by its message alone
  NotConverged,   // fErr > tol after NRitMax passes, no pattern recognised
  Stalled,        // the residual stopped falling far above round-off
  StillFalling,   // it was still falling: more passes (the message names NRitMax)
  AtFloor,        // it stalled at its round-off floor: a larger tol (the message names one)
  NotFinite,      // a NaN or Inf in the residual
  Singular,       // Kt(fd,fd) could not be factorised or solved
  LeftGrid,       // a material point left the background grid
  Inverted,       // a converged state with det F <= 0 at a point (a loose tol, or too large a step)
  DomainTooLarge  // a GIMP domain overlaps more than 3 x 3 cells (elemForMP; the remedy: split=)
};
struct RunError : std::runtime_error {
  Failure kind = Failure::Other;
  explicit RunError(const std::string& what, Failure k = Failure::Other) : std::runtime_error(what), kind(k) {}
};
// the Newton-Raphson loop of a load step failed (no convergence, NaN, singular
// stiffness): the one failure that a smaller load step may cure
struct NewtonFailure : RunError {
  using RunError::RunError;
};

}  // namespace ample
