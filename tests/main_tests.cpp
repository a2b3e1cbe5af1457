//--------------------------------------------------------------------------
// main_tests — doctest main of the ample-cpp test suite (see tests/CMakeLists.txt)
//--------------------------------------------------------------------------
// The default reporter "exercises" is doctest's console reporter, except for a
// blanked exercise of the student copy (constitutive/exercise.h, docs/exercises.md).
// A test case that reaches ExerciseNotDone("X: ...") prints ONE line and
// nothing else of that test case:
//   in the suite of an exercise S (the suites named like the exercises of the
//   BEGIN EXERCISE markers, AMPLE_EXERCISES from CMake): a failure,
//     "FAILED: exercise X not done: see docs/exercises.md#X"  (X = S), or
//     "FAILED: exercise S cannot be graded before exercise X: see ..." (X != S);
//   in any other suite: a skip, "needs exercise X: skipped ..." (CTest's
//     SKIP_REGULAR_EXPRESSION turns it into a skipped test; the exit status
//     counts it as passed when nothing else failed).
// AMPLE_EXERCISE_LOG=file (environment) appends one line per test case,
//   status<TAB>suite<TAB>exercise<TAB>test case, status pass, fail, graded or
//   needs (tools/check_student.sh reads it).
// Tests: tests/test_exercises.cpp; the student copy in .ci/run.
//--------------------------------------------------------------------------
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>
#include "constitutive/exercise.h"
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#ifndef AMPLE_EXERCISES
#define AMPLE_EXERCISES ""
#endif

namespace {

const std::string tag = "ExerciseNotDone: ";

bool isExercise(const std::string& suite) {  // AMPLE_EXERCISES: "a,b,c"
  static const std::set<std::string> names = [] {
    std::set<std::string> s;
    std::istringstream in(AMPLE_EXERCISES);
    for (std::string n; std::getline(in, n, ',');) s.insert(n);
    return s;
  }();
  return names.count(suite) > 0;
}

// the exercise named by a translated exception, "" for any other exception
std::string exerciseIn(const std::string& what) {
  const size_t p = what.find(tag);
  if (p == std::string::npos) return "";
  const size_t q = p + tag.size();
  return what.substr(q, what.find(':', q) - q);
}

struct Counts {
  int graded = 0, needs = 0, other = 0;  // test cases
  int needsAssertsFailed = 0;            // failed assertions of the skipped ones
} counts;

struct ExerciseReporter : doctest::ConsoleReporter {
  using ConsoleReporter::ConsoleReporter;
  std::string suite, name, file, exercise;
  int line = 0;

  void test_case_start(const doctest::TestCaseData& in) override {
    suite = in.m_test_suite;
    name = in.m_name;
    file = in.m_file.c_str();
    line = in.m_line;
    exercise.clear();
    ConsoleReporter::test_case_start(in);
  }
  bool grading() const { return isExercise(suite); }
  // true: the exercise's one line is printed (now or before), the event is not shown
  bool handled(const std::string& what) {
    if (!exercise.empty()) return true;
    exercise = exerciseIn(what);
    if (exercise.empty()) return false;
    const std::string see = ": see docs/exercises.md#" + exercise;
    if (!grading())
      s << "needs exercise " << exercise << ": skipped \"" << name << "\" (suite " << suite << ")" << see << "\n";
    else if (exercise == suite)
      s << file << ":" << line << ": FAILED: exercise " << exercise << " not done" << see << "\n";
    else
      s << file << ":" << line << ": FAILED: exercise " << suite << " cannot be graded before exercise "
        << exercise << see << "\n";
    return true;
  }
  void test_case_exception(const doctest::TestCaseException& e) override {
    if (!handled(e.error_string.c_str())) ConsoleReporter::test_case_exception(e);
  }
  void log_assert(const doctest::AssertData& a) override {
    if (!exercise.empty()) return;
    if (a.m_failed && a.m_threw && handled(a.m_exception.c_str())) return;
    ConsoleReporter::log_assert(a);
  }
  void log_message(const doctest::MessageData& m) override {
    if (exercise.empty()) ConsoleReporter::log_message(m);
  }
  void test_case_end(const doctest::CurrentTestCaseStats& st) override {
    std::string status = st.failure_flags ? "fail" : "pass";
    if (exercise.empty()) {
      counts.other += st.failure_flags ? 1 : 0;
      ConsoleReporter::test_case_end(st);
    } else {
      status = grading() ? "graded" : "needs";
      (grading() ? counts.graded : counts.needs)++;
      if (!grading()) counts.needsAssertsFailed += st.numAssertsFailedCurrentTest;
    }
    if (const char* log = std::getenv("AMPLE_EXERCISE_LOG"))
      std::ofstream(log, std::ios::app) << status + "\t" + suite + "\t" + exercise + "\t" + name + "\n";
  }
  void test_run_end(const doctest::TestRunStats& stats) override {
    doctest::TestRunStats p = stats;  // a "needs exercise" test case counts as skipped
    p.numTestCasesPassingFilters -= counts.needs;
    p.numTestCasesFailed -= counts.needs;
    p.numAssertsFailed -= counts.needsAssertsFailed;
    ConsoleReporter::test_run_end(p);
    if (counts.graded + counts.needs > 0)
      s << "[exercises] " << counts.graded << " test cases failed on an exercise not done, "
        << counts.needs << " skipped (\"needs exercise\"), " << counts.other << " other failures\n";
  }
};

}  // namespace

DOCTEST_REGISTER_REPORTER("exercises", 1, ExerciseReporter);

DOCTEST_REGISTER_EXCEPTION_TRANSLATOR(const ample::ExerciseNotDone& e) {
  return doctest::String((tag + e.what()).c_str());
}

int main(int argc, char** argv) {
  doctest::Context ctx;
  ctx.setOption("reporters", "exercises");  // -r / --reporters on the command line still choose
  ctx.applyCommandLine(argc, argv);
  const int res = ctx.run();
  if (ctx.shouldExit()) return res;
  // only skips: "needs exercise X" is no failure
  if (res != 0 && counts.needs > 0 && counts.other == 0 && counts.graded == 0) return 0;
  return res;
}
