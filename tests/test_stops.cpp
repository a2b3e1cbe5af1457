// Tests of how a run ends when it cannot finish (ample.cpp, loadSteps.cpp whatToTry,
// writeOutput.cpp, the setups' results): every exit path leaves complete, valid output, a
// figure that is undefined is null with its reason, and each stop message names a remedy
// that, followed, completes the run.
#include "setups/program/run.h"
#include "ample/errors.h"
#include "ample/remedies/loadSteps.h"
#include "setups/setupHelpers.h"
#include "testProblems.h"
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>
#include <sys/wait.h>
#include <unistd.h>

using namespace ample;

namespace {
struct Run {
  int code;             // exit status
  std::string err;      // stderr
  std::string dir;      // output folder
};
// the program on `args` (--quiet --vtk 0 and its own output folder added)
Run runProgram(const std::string& args, const std::string& name) {
  const std::string dir = std::string(AMPLE_TEST_TMP) + "/stops_" + name;
  std::filesystem::create_directories(AMPLE_TEST_TMP);
  const std::string err = dir + ".err";
  const std::string cmd = std::string(AMPLE_BINARY) + " " + args + " --quiet --vtk 0 --out " + dir +
                          " >/dev/null 2>" + err;
  const int st = std::system(cmd.c_str());
  Run r{WIFEXITED(st) ? WEXITSTATUS(st) : -1, testing::fileText(err), dir};
  if (r.code == 3) throw ExerciseNotDone("(the student copy): " + r.err);
  return r;
}
// the value after `key=` in a message's advice (after its "try " or "e.g. "), e.g. "0.01" for
// key "ghost"; the first such value is the stop's (the run's notes, a loose tol's warning, follow it)
std::string advised(const std::string& message, const std::string& key) {
  const size_t t = std::min(message.find("try "), message.find("e.g. "));
  if (t == std::string::npos) return "";
  const std::string advice = message.substr(t);
  std::smatch m;
  const std::regex re("\\b" + key + "=([-+0-9.e]+)");
  return std::regex_search(advice, m, re) ? m[1].str() : "";
}
// a token no JSON parser reads, or a NaN/Inf written by a C++ stream
bool hasNonFinite(const std::string& text) {
  return std::regex_search(text, std::regex("(^|[^A-Za-z_])-?(nan|inf|NaN|Inf|Infinity)([^A-Za-z_]|$)"));
}
// the fields of one CSV line, empty ones kept (a last empty field too: "1,2," is 3 fields)
std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> f(1);
  for (const char c : line) {
    if (c == ',') f.emplace_back();
    else f.back() += c;
  }
  return f;
}
// the whole field one finite decimal number, as a strict reader takes it: no word ("nan",
// "inf", "not_finite"), no space, no hex (which strtod alone would read), nothing after it
bool isNumber(const std::string& f) {
  if (f.empty() || f.find_first_not_of("0123456789+-.eE") != std::string::npos) return false;
  char* end = nullptr;
  const double v = std::strtod(f.c_str(), &end);
  return end == f.c_str() + f.size() && std::isfinite(v);
}
// the fields of the CSV files in dir that are not numbers, as "file row column: 'field'"
// (empty where allowed: the fErr of a pass that went NaN, a setup's history figure that is
// not finite); checked: how many files and how many empty fields there were
struct CsvCheck {
  std::vector<std::string> bad;
  int files = 0, empty = 0;
};
CsvCheck checkCsvFields(const std::string& dir) {
  CsvCheck c;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() != ".csv") continue;
    const std::string file = e.path().filename().string();
    c.files++;
    std::ifstream in(e.path());
    std::string line;
    std::getline(in, line);                               // the header: the columns' names
    const std::vector<std::string> names = csvFields(line);
    for (int row = 1; std::getline(in, line); ++row) {
      const std::vector<std::string> f = csvFields(line);
      if (f.size() != names.size()) c.bad.push_back(file + " row " + std::to_string(row) + ": " +
                                                    std::to_string(f.size()) + " fields");
      for (size_t k = 0; k < std::min(f.size(), names.size()); ++k) {
        const bool mayBeEmpty = file == "history.csv" || names[k] == "fErr";
        if (f[k].empty() && mayBeEmpty) c.empty++;
        else if (!isNumber(f[k])) c.bad.push_back(file + " row " + std::to_string(row) + " " + names[k] + ": '" + f[k] + "'");
      }
    }
  }
  return c;
}
// the first line of a text
std::string firstLine(const std::string& text) { return text.substr(0, text.find('\n')); }

// a run whose first Newton pass overflows (test "a non-finite residual ..." below)
const char* const notFinite = "compaction nelsy=4 lstps=1 E=1e-300";
}  // namespace

TEST_SUITE("stops") {
  TEST_CASE("stops: every setup's results() measures any state, none converged included") {
    for (const Setup& s : setupsTable()) {
      CAPTURE(s.name);
      Params P = s.params();
      if (std::string(s.name) == "ibcantilever") setParam(P, "h", 0.005), setParam(P, "mp", 2);
      const Analysis an = s.setupGrid(P);                 // no step taken: uvw, history empty
      const Results r = s.results(an, P);
      for (const auto& f : r) {
        CAPTURE(f.first);
        bool why = false;
        for (const auto& w : r.why) why = why || w.first == f.first;
        CHECK((std::isfinite(f.second) || why));          // finite, or undefined with a reason
      }
    }
  }

  TEST_CASE("stops: a zero load gives null figures with their reason, and JSON without NaN") {
    const Run r = runProgram("compaction nelsy=4 rho=0", "noload");
    REQUIRE(r.code == 0);
    const std::string json = testing::fileText(r.dir + "/summary.json");
    CHECK_FALSE(hasNonFinite(json));
    CHECK(json.find("\"error\": null") != std::string::npos);
    CHECK(json.find("\"results_undefined\": {\"error\": \"no load") != std::string::npos);
  }

  TEST_CASE("stops: a run that fails in its first step leaves summary, steps and the initial state") {
    const Run r = runProgram("squeeze tol=1e-30 NRitMax=2", "firststep");
    REQUIRE(r.code == 1);
    const std::string json = testing::fileText(r.dir + "/summary.json");
    CHECK(json.find("\"converged\": false") != std::string::npos);
    CHECK(json.find("\"last_converged_step\": 0") != std::string::npos);
    CHECK(json.find("load step 1 did not converge") != std::string::npos);
    CHECK_FALSE(hasNonFinite(json));
    const testing::CsvTable steps = testing::readCsvTable(r.dir + "/steps.csv");
    REQUIRE(steps.rows.size() == 1);
    CHECK(steps.at(0, "converged") == 0);
    const testing::CsvTable mp = testing::readCsvTable(r.dir + "/mp_final.csv");
    REQUIRE(mp.rows.size() == 64);                        // nels = 4: 4 x 4 cells x 2 x 2 points
    for (size_t p = 0; p < mp.rows.size(); ++p) {         // the initial state: nothing moved
      CHECK(mp.at(p, "x") == mp.at(p, "X0"));
      CHECK(mp.at(p, "y") == mp.at(p, "Y0"));
      CHECK(mp.at(p, "syy") == 0.0);
    }
  }

  // A residual that is not finite, for certain: E = 1e-300 Pa moves the column by some 1e304 m in
  // the first pass, whose b = F F' overflows. (A Newton pass that diverges reaches one too, but
  // in which pass, or whether a singular stiffness comes first, is round-off's choice.)
  TEST_CASE("stops: a non-finite residual is written as an empty fErr field") {
    const Run r = runProgram(notFinite, "notfinite");
    REQUIRE(r.code == 1);
    CHECK(r.err.find("load step 1, Newton-Raphson pass 1: the residual is not finite") != std::string::npos);
    const std::string res = testing::fileText(r.dir + "/residuals.csv");
    CHECK(res.find("\n1,0,1\n1,1,\n") != std::string::npos);   // step 1: pass 0 fErr = 1, pass 1 empty
    CHECK(testing::fileText(r.dir + "/steps.csv").find("\n1,1,1,,0,") != std::string::npos);
    CHECK_FALSE(hasNonFinite(res));
    CHECK_FALSE(hasNonFinite(testing::fileText(r.dir + "/steps.csv")));
    // what to try: halves of the failed step, or twice the load steps (neither helps this one)
    CHECK(advised(r.err, "substeps") == "4");
    CHECK(advised(r.err, "lstps") == "2");
  }

  // No column is text by design: writeOutput.cpp writes numbers only (converged as 0 or 1) and
  // history.csv the setups' figures (Analysis::history: name and double). Empty is allowed in
  // the fErr columns and in history.csv, where a number is not finite (docs/output.md).
  TEST_CASE("stops: every field of every CSV of a stopped run is a finite number, or empty where undefined") {
    // the residual not finite in step 1 (steps.csv, residuals.csv and mp_final.csv), and step 27
    // of the shear not converging in 3 passes (fErr 0.97) after 26 that did (history.csv too)
    const Run nan = runProgram(notFinite, "csv_notfinite");
    const Run stuck = runProgram("shear mp=2 NRitMax=3", "csv_notconverged");
    REQUIRE(nan.code == 1);
    REQUIRE(stuck.code == 1);
    CHECK(nan.err.find("the residual is not finite") != std::string::npos);
    CHECK(stuck.err.find("load step 27 did not converge") != std::string::npos);
    const CsvCheck a = checkCsvFields(nan.dir), b = checkCsvFields(stuck.dir);
    CHECK(a.files == 3);
    CHECK(b.files == 4);
    CHECK(a.empty == 2);                                  // the last pass's fErr, and its step's
    CHECK(b.empty == 0);
    for (const std::string& f : a.bad) FAIL_CHECK(f);
    for (const std::string& f : b.bad) FAIL_CHECK(f);
    CHECK(a.bad.empty());
    CHECK(b.bad.empty());
  }

  // A run says other things on stderr (a loose tol's warning, a step accepted at its round-off
  // floor, a solver's LU fallback): they are kept (RunLog::notes) and said after the reason of a
  // stop, or at the end of a run that completes. Before, each was said when it happened, so it
  // came first in the first three cases below, and the first line named no reason.
  TEST_CASE("stops: the first stderr line of a non-zero exit names the reason, the run's other lines after it") {
    struct Case {
      const char* args;
      int code;
      const char* reason;   // in the first line
      const char* note;     // in a later line (nullptr: none at all)
    };
    const Case cases[] = {
        // a step that does not converge, under a loose tol (said at the start before)
        {"compaction NRitMax=2 tol=0.0011", 1, "load step 1 did not converge", "warning: tol=0.0011"},
        // the residual not finite, under a loose tol
        {"compaction nelsy=4 lstps=1 E=1e-300 tol=0.002", 1, "the residual is not finite", "warning: tol=0.002"},
        // --accept-floor accepts steps 1-15 at their floor (a line each, said as accepted before),
        // then a step does not converge (16 when measured)
        {"collapse tol=1e-16 --accept-floor NRitMax=6", 1, "did not converge",
         "ample: load step 1 accepted at its round-off floor (--accept-floor)"},
        // bad input: refused before any run, so no warning at all; the parameter is named
        {"compaction tol=2", 2, "parameter 'tol' = 2 is out of range", nullptr},
        // bad input found by the setup: its message alone, no warning of the loose tol
        {"ibcantilever E=556278 tol=0.5", 2, "exceeds the beam's length", nullptr},
    };
    int n = 0;
    for (const Case& c : cases) {
      CAPTURE(c.args);
      const Run r = runProgram(c.args, "firstline_" + std::to_string(n++));
      CAPTURE(r.err);
      CHECK(r.code == c.code);
      const std::string first = firstLine(r.err);
      CHECK(first.rfind("ample: ", 0) == 0);
      CHECK(first.find(c.reason) != std::string::npos);
      const size_t note = c.note ? r.err.find(c.note) : r.err.find("warning");
      if (c.note) CHECK((note != std::string::npos && note > first.size()));  // kept, and after it
      else CHECK(note == std::string::npos);
    }
    // a run that completes still says its notes, at its end
    const Run done = runProgram("compaction tol=0.002", "firstline_done");
    CHECK(done.code == 0);
    CHECK(done.err.find("warning: tol=0.002 accepts load steps") != std::string::npos);
  }

  TEST_CASE("stops: a residual stalled far above round-off is never accepted at a floor") {
    // E = 1e30 against a load of order 1e4: fErr stays 1.0; its floor estimate is ~5e10
    const Run r = runProgram("compaction nelsy=4 lstps=2 E=1e30 --accept-floor", "nofloor");
    CHECK(r.code == 1);
    CHECK(r.err.find("accepted at its round-off floor") == std::string::npos);
    CHECK(r.err.find("far above round-off") != std::string::npos);
    CHECK(advised(r.err, "tol").empty());                 // no tol is advised: none would help
  }

  TEST_CASE("stops: the tol advised at a round-off floor is inside tol's range and passes") {
    const Run r = runProgram("deepbeam h=0.02 mp=2 NRitMax=2 tol=1e-20", "tol");
    REQUIRE(r.code == 1);
    const std::string tol = advised(r.err, "tol");
    REQUIRE_FALSE(tol.empty());
    CHECK(std::stod(tol) < 1e-6);                         // (0, 1), and at most 1e-6 (maxFloor)
    CHECK(runProgram("deepbeam h=0.02 mp=2 NRitMax=2 tol=" + tol, "tol_followed").code == 0);
  }

  TEST_CASE("stops: a singular stiffness names the ghost penalty, which completes the run") {
    const Run r = runProgram("ibcantilever h=0.01 mp=2", "singular");
    REQUIRE(r.code == 1);
    CHECK(r.err.find("singular") != std::string::npos);
    REQUIRE(advised(r.err, "ghost") == "0.01");
    CHECK(runProgram("ibcantilever h=0.01 mp=2 ghost=0.01", "singular_ghost").code == 0);
  }

  TEST_CASE("stops: too few Newton-Raphson passes name the paper's NRitMax, which completes the run") {
    const Run r = runProgram("compaction NRitMax=2", "fewpasses");
    REQUIRE(r.code == 1);
    REQUIRE(advised(r.err, "NRitMax") == "10");
    CHECK(runProgram("compaction NRitMax=10", "fewpasses_followed").code == 0);
  }

  TEST_CASE("stops: a singular stiffness from a large load step names substeps too, which completes it") {
    // a 4.2 km column under its own weight: the first step empties cells (no rigid-body mode)
    const Run r = runProgram("compaction l0=4165.31", "singular_large");
    REQUIRE(r.code == 1);
    CHECK(r.err.find("singular") != std::string::npos);
    CHECK(advised(r.err, "ghost") == "0.01");
    REQUIRE(advised(r.err, "substeps") == "4");
    CHECK(runProgram("compaction l0=4165.31 substeps=4", "singular_large_halves").code == 0);
  }

  TEST_CASE("stops: a domain that outgrew its cells or a failed step with stretched domains names split") {
    Analysis an = testing::smallBlock(MpType::GIMP, CmType::Elastic, 2);   // h = 1, lp = 0.25
    const RunError tooLarge("domain too large", Failure::DomainTooLarge), diverged("diverged", Failure::NotConverged);
    CHECK(advised(whatToTry(tooLarge, an, 1000), "split") == "0.5");
    CHECK(whatToTry(diverged, an, 1000).find("split") == std::string::npos);  // lp = h/4: not named
    an.mpData[0].lp(0) = 0.7;                                                  // stretched past h/2
    CHECK(advised(whatToTry(diverged, an, 1000), "split") == "0.5");
    CHECK(whatToTry(RunError("singular", Failure::Singular), an, 1000).find("split=0.5") != std::string::npos);
    an.split = 0.5;                                                            // already on
    CHECK(whatToTry(diverged, an, 1000).find("split") == std::string::npos);
  }

  TEST_CASE("stops: a point that leaves the grid names the setup's wider grid, which completes the run") {
    const Run r = runProgram("collapse width=9", "leftgrid");
    REQUIRE(r.code == 1);
    CHECK(r.err.find("has left the background grid") != std::string::npos);
    REQUIRE(advised(r.err, "width") == "18");
    CHECK(runProgram("collapse width=18", "leftgrid_wider").code == 0);
  }

  TEST_CASE("stops: a state with an inverted point (det F <= 0) is never accepted, even by a loose tol") {
    // tol = 0.82 accepts steps whose residual is of order one; in step 27 a point's det F is
    // -2.2, whose volume (eq 15) and GIMP domain (sqrt of it) would be written as -nan
    const Run r = runProgram("shear nu=0.250686 cmType=1 mp=2 tol=0.822897", "inverted");
    REQUIRE(r.code == 1);
    CHECK(r.err.find("is inverted (det F = ") != std::string::npos);
    CHECK(!hasNonFinite(testing::fileText(r.dir + "/mp_final.csv")));
    CHECK(!hasNonFinite(testing::fileText(r.dir + "/summary.json")));
    REQUIRE(advised(r.err, "tol") == "1e-9");
    // the loose tol had hidden a step that fails: at the paper's tol the same step stops (the
    // 2x2-point shear fails in step 27 at any tol; its Newton passes diverge, and whether the
    // tenth pass or a non-finite residual ends them is round-off's choice)
    const Run t = runProgram("shear nu=0.250686 cmType=1 mp=2 tol=1e-9", "inverted_tol");
    CHECK(t.code == 1);
    CHECK(firstLine(t.err).find("load step 27") != std::string::npos);
  }

  TEST_CASE("stops: ibcantilever refuses a load whose beam deflection would size the grid without bound") {
    const Run r = runProgram("ibcantilever E=556278", "unbounded");
    CHECK(r.code == 2);
    CHECK(r.err.find("b = 2e+08 N/m3 with E = 556278 Pa") != std::string::npos);
    CHECK(r.err.find("exceeds the beam's length L = 0.1 m") != std::string::npos);
    CHECK(r.err.find("E >= 7.14e+08") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(r.dir + "/summary.json"));
  }

  TEST_CASE("stops: more points than the memory holds is refused before any work, with the bytes a point needs") {
    const size_t perPoint = sizeof(MaterialPoint);                  // the basis inside
    CHECK_NOTHROW(checkPointMemory(1000));                           // 1000 points: well inside
    try {
      checkPointMemory(size_t(1) << 42);                               // 4.4e12 points: PBs
      FAIL("no InputError");
    } catch (const InputError& e) {
      const std::string m = e.what();
      CHECK(m.find(std::to_string(perPoint) + " bytes each") != std::string::npos);
      CHECK(m.find("use fewer points") != std::string::npos);
      CHECK(m.find("converged copy") == std::string::npos);
    }
  }
}
