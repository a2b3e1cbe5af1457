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
#include "exercise.h"  // ExerciseNotDone: a blanked exercise of the student copy
#include <stdexcept>
#include <string>

namespace ample {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
struct RunError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// the Newton-Raphson loop of a load step failed (no convergence, NaN, singular
// stiffness): the one failure that a smaller load step may cure
struct NewtonFailure : RunError {
  using RunError::RunError;
};

}  // namespace ample
