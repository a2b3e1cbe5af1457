//--------------------------------------------------------------------------
// exercise.h — the error of a blanked exercise in the student copy
//--------------------------------------------------------------------------
// tools/make_student_version.sh replaces each region of the source between
// `// BEGIN EXERCISE name` and `// END EXERCISE` by
//   throw ExerciseNotDone("name: see docs/exercises.md#name");
// It is no RunError or InputError, so that no remedy, retry or error path of
// the analysis catches it: the program (main.cpp) prints one line naming the
// exercise and exits with status 3; the test main (tests/main_tests.cpp)
// fails the exercise's own suite with one line and skips every other test
// with "needs exercise name". The full tree never throws it.
// Inputs:  what = "name: see docs/exercises.md#name"
// Outputs: exercise() = name
// It lives in constitutive/, the bottom of the tree, so that the material models
// (whose exercises throw it too) include nothing of ample/.
// Tests:   tests/test_exercises.cpp
//--------------------------------------------------------------------------
#pragma once
#include <stdexcept>
#include <string>

namespace ample {

struct ExerciseNotDone : std::logic_error {
  using std::logic_error::logic_error;
  std::string exercise() const {  // the name before the first ':'
    const std::string w = what();
    return w.substr(0, w.find(':'));
  }
};

}  // namespace ample
