// Tests of the classroom kit (docs/exercises.md): the error of a blanked exercise
// names it and is caught by no error path of the analysis; every exercise of the
// BEGIN EXERCISE markers has its anchor in docs/exercises.md (the message points
// there) and at least two wrong answers for tools/grading.sh.
#include "ample/errors.h"
#include <doctest/doctest.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

using namespace ample;

namespace {
std::vector<std::string> exerciseNames() {  // AMPLE_EXERCISES: "a,b,c" (tests/CMakeLists.txt)
  std::vector<std::string> v;
  std::istringstream in(AMPLE_EXERCISES);
  for (std::string n; std::getline(in, n, ',');) v.push_back(n);
  return v;
}
}  // namespace

TEST_SUITE("exercises") {
  TEST_CASE("exercises: ExerciseNotDone names its exercise and is no RunError or InputError") {
    const ExerciseNotDone e("VMconst: see docs/exercises.md#VMconst");
    CHECK(e.exercise() == "VMconst");
    CHECK(std::string(e.what()) == "VMconst: see docs/exercises.md#VMconst");
    CHECK_FALSE(std::is_base_of_v<RunError, ExerciseNotDone>);   // no retry or restore catches it
    CHECK_FALSE(std::is_base_of_v<InputError, ExerciseNotDone>);
    CHECK(std::is_base_of_v<std::logic_error, ExerciseNotDone>);
  }

  TEST_CASE("exercises: 15 exercises, each with its anchor in docs/exercises.md and wrong answers") {
    const std::vector<std::string> names = exerciseNames();
    CHECK(names.size() == 15);
    std::ifstream doc(std::string(AMPLE_SOURCE_DIR) + "/docs/exercises.md");
    REQUIRE(doc.good());
    const std::string text((std::istreambuf_iterator<char>(doc)), std::istreambuf_iterator<char>());
    for (const std::string& x : names) {
      CAPTURE(x);
      CHECK(text.find("<a id=\"" + x + "\"></a>") != std::string::npos);
      CHECK(text.find("ample_tests -ts=" + x) != std::string::npos);  // the command that grades it
      int wrong = 0;
      const std::filesystem::path dir = std::filesystem::path(AMPLE_SOURCE_DIR) / "tools/wrong_answers" / x;
      if (std::filesystem::is_directory(dir))
        for (const auto& f : std::filesystem::directory_iterator(dir)) wrong += f.path().extension() == ".inc";
      CHECK(wrong >= 2);
    }
  }
}
