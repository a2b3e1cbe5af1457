// Tests of the command line (cli.cpp, main.cpp): parameters parsed and
// checked, bad input refused with exit status 2 and no output written.
#include "setups/program/cli.h"
#include "ample/errors.h"
#include "setups/setups.h"
#include <doctest/doctest.h>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <random>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

using namespace ample;

namespace {
// the program's exit status; status 3 (the student copy reached an exercise not
// done, main.cpp) is passed on as ExerciseNotDone, so the test is skipped as "needs it"
int runBinary(const std::string& args, std::string* errText = nullptr) {
  const std::string err = std::string(AMPLE_TEST_TMP) + "/runBinary_" + std::to_string(::getpid()) + ".err";
  std::filesystem::create_directories(AMPLE_TEST_TMP);
  const std::string cmd = std::string(AMPLE_BINARY) + " " + args + " >/dev/null 2>" + err;
  const int st = std::system(cmd.c_str());
  const int code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  std::string line;
  std::getline(std::ifstream(err), line);
  if (errText) {
    std::ostringstream all;
    all << std::ifstream(err).rdbuf();
    *errText = all.str();
  }
  std::filesystem::remove(err);
  const std::string prefix = "ample: needs exercise ";
  if (code == 3 && line.rfind(prefix, 0) == 0) throw ExerciseNotDone(line.substr(prefix.size()));
  return code;
}
// the range of a parameter as the message should state it, e.g. "(-1, 0.5)" or "[1, 64]"
std::string rangeOf(const Param& p) {
  auto num = [](double v) {
    std::ostringstream s;
    if (std::isinf(v)) s << (v > 0 ? "inf" : "-inf"); else s << v;
    return s.str();
  };
  return (p.loOpen ? "(" : "[") + num(p.lo) + ", " + num(p.hi) + (p.hiOpen ? ")" : "]");
}
bool inside(const Param& p, double v) {
  return std::isfinite(v) && (p.loOpen ? v > p.lo : v >= p.lo) && (p.hiOpen ? v < p.hi : v <= p.hi) &&
         (!p.isInteger || v == std::floor(v));
}
// a choice's name as the command line reads it: in any case
bool sameName(std::string a, std::string b) {
  for (char& c : a) c = char(std::tolower(static_cast<unsigned char>(c)));
  for (char& c : b) c = char(std::tolower(static_cast<unsigned char>(c)));
  return a == b;
}
// the message of the InputError parseArgs throws on args; "" if it accepts them
std::string refusalOf(const std::vector<std::string>& args) {
  try {
    parseArgs(args);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }
const Param* paramOf(const Params& P, const std::string& name) {
  for (const Param& p : P)
    if (p.name == name) return &p;
  return nullptr;
}

// a parsed run: every value inside its range, and the last name=value of each name kept
bool parsedValuesValid(const CliRequest& r, const std::vector<std::string>& args) {
  bool ok = true;
  for (const Param& p : r.params) {
    if (inside(p, p.value())) continue;
    ok = false;
    MESSAGE("parameter " << p.name << " = " << p.value() << " outside " << rangeOf(p));
  }
  std::map<std::string, std::string> last;
  std::string vtk = "1";
  for (size_t i = 1; i < args.size(); ++i) {
    if (args[i] == "--out" || args[i] == "--vtk") {
      if (args[i] == "--vtk") vtk = args[i + 1];
      ++i;
      continue;
    }
    const size_t eq = args[i].find('=');
    if (eq != std::string::npos && eq > 0) last[args[i].substr(0, eq)] = args[i].substr(eq + 1);
  }
  for (const auto& kv : last) {
    const Param* p = paramOf(r.params, kv.first);
    if (!p) { MESSAGE("unknown name accepted: " << kv.first); ok = false; continue; }
    double v = std::strtod(kv.second.c_str(), nullptr);
    for (size_t k = 0; k < p->names.size(); ++k)
      if (sameName(kv.second, p->names[k])) v = p->lo + double(k);
    if (p->value() != v) { MESSAGE(kv.first << " = " << kv.second << " kept as " << p->value()); ok = false; }
  }
  if (r.options.vtkEvery != std::strtod(vtk.c_str(), nullptr)) ok = false;
  return ok;
}

// a refusal names the offending word in quotes; a value out of range names its parameter
// and the valid range, and is indeed outside it
bool refusalNamesOffender(const std::string& m, const std::vector<std::string>& args, int& ranges) {
  if (args.empty()) return m.find("no setup given") != std::string::npos;
  const Setup* s = findSetup(args[0]);
  const Params P = s ? s->params() : Params{};
  bool named = false;  // the setup name itself only counts when it is the offender
  for (size_t i = s ? 1 : 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const size_t eq = a.find('=');
    const std::string name = eq == std::string::npos ? a : a.substr(0, eq);
    if (m.find("'" + a + "'") != std::string::npos || m.find("'" + name + "'") != std::string::npos) named = true;
    if (!s || eq == std::string::npos) continue;
    const std::string text = a.substr(eq + 1);
    if (m.find("parameter '" + name + "' = " + text + " is out of range") != 0) continue;
    const Param* p = paramOf(P, name);  // a value refused as out of range
    if (!p) return false;
    ++ranges;
    const double v = std::strtod(text.c_str(), nullptr);
    bool isName = false;
    for (const std::string& n : p->names) isName = isName || sameName(n, text);
    if (m.find("allowed ") == std::string::npos || m.find(rangeOf(*p)) == std::string::npos) return false;
    if (!isName && inside(*p, v)) return false;  // a valid value refused
  }
  if (!named) MESSAGE("refusal does not name the offender: " << m);
  return named;
}
}  // namespace

TEST_SUITE("cli") {
  TEST_CASE("cli: parameters override the setup defaults") {
    const CliRequest r = parseArgs({"compaction", "nelsy=8", "E=2e4", "--vtk", "5", "--quiet",
                                    "--out", "x/y"});
    REQUIRE(r.mode == CliMode::Run);
    CHECK(r.params.named("nelsy").value() == 8);
    CHECK(r.params.named("E").value() == 2e4);
    CHECK(r.params.named("nu").value() == 0.0);  // untouched default
    CHECK(r.options.vtkEvery == 5);
    CHECK(r.options.quiet);
    CHECK(r.options.outDir == "x/y");
    CHECK(parseArgs({"beam"}).options.outDir == "output/beam");
    const CliRequest n = parseArgs({"collapse", "mpType=CPDI2", "formulation=PC", "domainUpdate=corner"});
    CHECK(n.params.named("mpType").value() == 4);  // values may be given by name
    CHECK(n.params.named("formulation").value() == 2);
    CHECK(n.params.named("domainUpdate").value() == 4);
    CHECK(parseArgs({"compaction", "formulation=SS"}).params.named("formulation").value() == 3);  // [Boundaries]
  }

  TEST_CASE("cli: bad input is refused with a message naming the parameter and range") {
    const std::vector<std::vector<std::string>> bad = {
        {},                          {"nosuchsetup"},           {"compaction", "E=-1"},
        {"compaction", "nu=0.5"},    {"compaction", "nu=-1"},   {"compaction", "nelsy=2.5"},
        {"compaction", "nelsy=0"},   {"compaction", "mp=abc"},  {"compaction", "foo=1"},
        {"compaction", "E="},        {"compaction", "=3"},      {"compaction", "E=nan"},
        {"compaction", "E=inf"},     {"compaction", "--vtk"},   {"compaction", "--vtk", "-1"},
        {"compaction", "--out"},     {"compaction", "mpType=5"}, {"compaction", "tol=0"},
        {"compaction", "stray"},     {"compaction", "mpType=CPDI3"}, {"compaction", "domainUpdate=7"}};
    for (const auto& args : bad) {
      CAPTURE(args.size());
      CHECK_THROWS_AS(parseArgs(args), InputError);
    }
    try {
      parseArgs({"compaction", "nu=0.7"});
    } catch (const InputError& e) {
      const std::string m = e.what();
      CHECK(m.find("'nu'") != std::string::npos);
      CHECK(m.find("(-1, 0.5)") != std::string::npos);
    }
  }

  TEST_CASE("cli: --vtk-format ascii (default) or binary / anything else is refused naming both") {
    CHECK(parseArgs({"compaction"}).options.vtkFormat == VtkFormat::Ascii);
    CHECK(parseArgs({"compaction", "--vtk-format", "binary"}).options.vtkFormat == VtkFormat::Binary);
    CHECK(has(refusalOf({"compaction", "--vtk-format", "binary", "--vtk-format", "ascii"}),
              "option '--vtk-format' is given twice"));  // given once
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
             {"compaction", "--vtk-format"}, {"compaction", "--vtk-format", "BINARY"},
             {"compaction", "--vtk-format", "xml"}, {"compaction", "--vtk-format", ""}}) {
      CAPTURE(args.size());
      std::string m;
      try {
        parseArgs(args);
      } catch (const InputError& e) {
        m = e.what();
      }
      CHECK(m.find("option '--vtk-format'") != std::string::npos);
      CHECK(m.find("allowed ascii (the default) or binary") != std::string::npos);
      if (args.size() == 3) CHECK(m.find("'" + args[2] + "'") != std::string::npos);
    }
    const std::string dir = std::string(AMPLE_TEST_TMP) + "/cli_vtkformat";
    std::filesystem::remove_all(dir);
    CHECK(runBinary("compaction nelsy=4 lstps=1 E=1e6 --vtk-format binary2 --out " + dir) == 2);
    CHECK(!std::filesystem::exists(dir));
    CHECK(usageText().find("--vtk-format F") != std::string::npos);
    CHECK(!parseArgs({"compaction"}).options.acceptFloor);         // the paper's: a stall fails
    CHECK(parseArgs({"compaction", "--accept-floor"}).options.acceptFloor);
  }

  TEST_CASE("cli: the program exits 2 on bad input and writes nothing") {
    const std::string dir = std::string(AMPLE_TEST_TMP) + "/cli_bad";
    std::filesystem::remove_all(dir);
    CHECK(runBinary("compaction E=-5 --out " + dir) == 2);
    CHECK(runBinary("nosuchsetup --out " + dir) == 2);
    CHECK(runBinary("compaction mp=1.5 --out " + dir) == 2);
    CHECK(runBinary("doughnut mpType=2 --out " + dir) == 2);  // GIMP on a general mesh
    CHECK(runBinary("annulus mpType=2 --out " + dir) == 2);
    CHECK(runBinary("doughnut fem=1 mpType=4 --out " + dir) == 2);
    CHECK(runBinary("compaction nelsy=4194304 mp=20 --out " + dir) == 2);  // 1.7e9 points: 3.6 TB
    CHECK(!std::filesystem::exists(dir));
    CHECK(runBinary("--list") == 0);
    CHECK(runBinary("collapse --help") == 0);
  }

  TEST_CASE("cli: locking=Fbar on a general mesh or in the finite element mode is refused before any work, naming locking") {
    const std::string dir = std::string(AMPLE_TEST_TMP) + "/cli_locking";
    std::filesystem::remove_all(dir);
    for (const char* args : {"annulus locking=Fbar", "doughnut locking=1", "doughnut fem=1 mpType=1 locking=Fbar"}) {
      CAPTURE(args);
      std::string err;
      CHECK(runBinary(std::string(args) + " --out " + dir, &err) == 2);
      CHECK(err.find("locking=Fbar") != std::string::npos);
      CHECK(err.find("locking=none") != std::string::npos);   // what to use instead
    }
    CHECK(!std::filesystem::exists(dir));
  }

  TEST_CASE("cli: the program exits 0 on a converged run and 1 on a failed one") {
    const std::string dir = std::string(AMPLE_TEST_TMP) + "/cli_run";
    CHECK(runBinary("compaction nelsy=4 lstps=2 E=1e6 --vtk 0 --quiet --out " + dir) == 0);
    CHECK(runBinary("collapse lstps=2 NRitMax=2 --vtk 0 --quiet --out " + dir) == 1);
  }
}

TEST_SUITE("cli") {
  TEST_CASE("cli: random and malformed arguments never crash the parser (seeded fuzz)") {
    std::mt19937 gen(20261123);
    const std::vector<std::string> words = {
        "compaction", "beam", "collapse", "shear", "stretch", "--out", "--vtk", "--quiet", "--help",
        "--list", "-h", "nelsy=", "nelsy=8", "E=1e300", "E=-0", "nu=0.49999", "mp=0", "mpType=GIMP",
        "mpType=gimp", "=", "==", "a=b=c", "lstps=1e9", "tol=1e-400", "0", "-1", "1e", "nan", "",
        "domainUpdate=corner", "formulation=PC", "substeps=31", "dl=50", "x"};
    std::uniform_int_distribution<int> pick(0, int(words.size()) - 1), len(0, 7), byte(1, 255);
    int parsed = 0, refused = 0, runs = 0, ranges = 0, bad = 0;
    for (int trial = 0; trial < 20000; ++trial) {
      std::vector<std::string> args;
      for (int k = len(gen); k > 0; --k) {
        std::string w = words[pick(gen)];
        if (gen() % 5 == 0) w += char(byte(gen));   // a random byte appended
        if (gen() % 7 == 0 && !w.empty()) w[gen() % w.size()] = char(byte(gen));
        args.push_back(w);
      }
      CAPTURE(args.size());
      try {
        const CliRequest r = parseArgs(args);
        ++parsed;
        if (r.mode == CliMode::Run) {
          ++runs;
          bad += !parsedValuesValid(r, args);
        }
      } catch (const InputError& e) {  // the only exception allowed
        ++refused;
        bad += !refusalNamesOffender(e.what(), args, ranges);
      }
    }
    CHECK(bad == 0);          // every parsed list inside its ranges, every refusal named
    CHECK(runs > 100);        // both outcomes are exercised
    CHECK(refused > 100);
    CHECK(ranges > 10);       // including refusals of a value out of its range
  }
}

TEST_SUITE("cli") {
  TEST_CASE("cli: a value that is not a plain decimal number is refused (hex, inf, nan, spaces)") {
    // strtod alone would read 0x2710 as 10000, and accept inf, nan and a leading space
    for (const std::string text : {"0x2710", "0X1p3", "inf", "-inf", "nan", "infinity", " 5", "5 ",
                                    "1e", "1e+", ".", "+", "e5", "1,5", "1e4x"}) {
      CAPTURE(text);
      const std::string m = refusalOf({"compaction", "E=" + text});
      CHECK(has(m, "parameter 'E'"));
      CHECK(has(m, "'" + text + "' is not a plain decimal number"));
    }
    const std::map<std::string, double> plain = {{"2e4", 2e4}, {"+5", 5}, {".5", 0.5}, {"5.", 5},
                                                 {"1E3", 1e3}, {"20000", 2e4}, {"2.5e-3", 2.5e-3}};
    for (const auto& kv : plain) {
      CAPTURE(kv.first);
      CHECK(parseArgs({"compaction", "E=" + kv.first}).params.named("E").value() == kv.second);
    }
  }

  TEST_CASE("cli: an integer parameter must be written as a whole number (digits, optional sign)") {
    const Params P = findSetup("compaction")->params();
    for (const std::string arg : {"lstps=1e1", "lstps=10.0", "lstps=10.", "mpType=2.0", "nelsy=8e0"}) {
      CAPTURE(arg);
      const std::string name = arg.substr(0, arg.find('='));
      const std::string m = refusalOf({"compaction", arg});
      CHECK(has(m, "parameter '" + name + "'"));
      CHECK(has(m, "is not a whole number"));
      CHECK(has(m, rangeText(*paramOf(P, name))));  // e.g. "integer in [1, 1e+06]"
    }
    CHECK(parseArgs({"compaction", "lstps=10"}).params.named("lstps").value() == 10);
    CHECK(parseArgs({"compaction", "nelsy=+8"}).params.named("nelsy").value() == 8);
  }

  TEST_CASE("cli: a parameter or an option given twice is refused, naming it") {
    CHECK(has(refusalOf({"compaction", "E=1e4", "E=2e4"}), "parameter 'E' is given twice"));
    CHECK(has(refusalOf({"compaction", "E=1e4", "nu=0.2", "E=1e4"}), "parameter 'E' is given twice"));
    CHECK(has(refusalOf({"compaction", "--out", "a", "--out", "b"}), "option '--out' is given twice"));
    CHECK(has(refusalOf({"compaction", "--vtk", "1", "--vtk", "2"}), "option '--vtk' is given twice"));
    CHECK(has(refusalOf({"compaction", "--quiet", "--quiet"}), "option '--quiet' is given twice"));
    CHECK(refusalOf({"compaction", "E=1e4", "nu=0.2", "--out", "a", "--vtk", "1"}).empty());
  }

  TEST_CASE("cli: an option's value that is missing or is another option is refused") {
    CHECK(has(refusalOf({"compaction", "--out", "--quiet"}), "option '--out' needs a folder name"));
    CHECK(has(refusalOf({"compaction", "--out"}), "option '--out' needs a folder name"));
    CHECK(has(refusalOf({"compaction", "--out", ""}), "option '--out' needs a folder name"));
    CHECK(has(refusalOf({"compaction", "--vtk", "--quiet"}), "option '--vtk' needs a whole number"));
    CHECK(has(refusalOf({"compaction", "--vtk-format", "--out", "x"}), "option '--vtk-format' needs a value"));
    CHECK(has(refusalOf({"compaction", "--vtk", "1e1"}), "option '--vtk' = '1e1'"));
    // the program: exit 2, and no folder named after the option
    const std::string dir = "--quiet";
    std::filesystem::remove_all(dir);
    std::string err;
    CHECK(runBinary("compaction nelsy=4 lstps=1 --vtk 0 --out --quiet", &err) == 2);
    CHECK(has(err, "option '--out' needs a folder name"));
    CHECK(!std::filesystem::exists(dir));
    std::filesystem::remove_all(dir);
  }

  TEST_CASE("cli: --list, --help and <setup> --help take no other arguments") {
    CHECK(has(refusalOf({"--list", "extra"}), "'--list' takes no other arguments; remove 'extra'"));
    CHECK(has(refusalOf({"--help", "extra"}), "'--help' takes no other arguments; remove 'extra'"));
    CHECK(has(refusalOf({"-h", "compaction"}), "remove 'compaction'"));
    CHECK(has(refusalOf({"compaction", "--help", "extra"}), "remove 'extra'"));
    CHECK(has(refusalOf({"compaction", "--out", "x", "--help"}), "remove '--out'"));
    CHECK(parseArgs({"--list"}).mode == CliMode::List);
    CHECK(parseArgs({"--help"}).mode == CliMode::Help);
    CHECK(parseArgs({"compaction", "-h"}).mode == CliMode::SetupHelp);
    std::string err;
    CHECK(runBinary("--list extra", &err) == 2);
    CHECK(has(err, "remove 'extra'"));
    CHECK(runBinary("--help extra") == 2);
  }

  TEST_CASE("cli: each parameter of every setup sets a member of its own, and a fresh table has the defaults") {
    for (const Setup& s : setupsTable()) {
      const std::string setup = s.name;
      CAPTURE(setup);
      Params P = s.params();
      std::vector<double> before;
      for (const Param& p : P) before.push_back(p.value());
      for (size_t k = 0; k < P.size(); ++k) {
        const Param& p = P[k];
        CAPTURE(p.name);
        if (p.lo == p.hi) continue;  // one value allowed (e.g. lstps of the one-step setups)
        const double d = before[k];  // another valid value: one step (whole) or half way to a bound
        const double v = p.isInteger ? (d + 1 <= p.hi ? d + 1 : d - 1)
                                     : d < p.hi && std::isfinite(p.hi) ? 0.5 * (d + p.hi)
                                                                       : 0.5 * (d + p.lo);
        REQUIRE(inside(p, v));
        REQUIRE(v != d);
        p.set(v);
        CHECK(p.value() == v);
        for (size_t j = 0; j < P.size(); ++j)
          if (j != k && P[j].value() != before[j]) FAIL_CHECK(P[j].name << " moved with " << p.name);
        p.set(d);
      }
      const Params fresh = s.params();
      for (size_t k = 0; k < P.size(); ++k) CHECK(fresh[k].value() == before[k]);
    }
  }

  TEST_CASE("cli: a choice's name is read in any case, an unknown one lists the names and numbers") {
    for (const std::string name : {"gimp", "GIMP", "Gimp", "gImP"}) {
      CAPTURE(name);
      CHECK(parseArgs({"compaction", "mpType=" + name}).params.named("mpType").value() == 2);
    }
    CHECK(parseArgs({"compaction", "domainUpdate=CORNER"}).params.named("domainUpdate").value() == 4);
    CHECK(parseArgs({"compaction", "solver=ldlt"}).params.named("solver").value() == 1);
    CHECK(parseArgs({"compaction", "formulation=pc"}).params.named("formulation").value() == 2);
    CHECK(has(refusalOf({"compaction", "mpType=foo"}),
              "parameter 'mpType' = 'foo': allowed 1 MPM, 2 GIMP, 3 CPDI1, 4 CPDI2"));
    CHECK(has(refusalOf({"compaction", "cmType=vonmises"}), "parameter 'cmType' = 'vonmises': allowed 1 elastic, 2 VM"));
  }

  TEST_CASE("cli: any finite double is accepted, subnormals too, only overflow is not finite") {
    // strtod sets ERANGE on a subnormal result as on overflow; only the latter is bad input
    CHECK(parseArgs({"compaction", "E=1e-320"}).params.named("E").value() == std::strtod("1e-320", nullptr));
    CHECK(parseArgs({"compaction", "E=4.9e-324"}).params.named("E").value() > 0);  // the least subnormal
    CHECK(parseArgs({"compaction", "E=1.7e308"}).params.named("E").value() == 1.7e308);
    for (const std::string text : {"1e400", "-1e309", "2e308"}) {
      CAPTURE(text);
      const std::string m = refusalOf({"compaction", "E=" + text});
      CHECK(has(m, "parameter 'E'"));
      CHECK(has(m, "overflows a double"));
    }
    // 1e-400 rounds to 0, which is outside E's range (0, inf)
    CHECK(has(refusalOf({"compaction", "E=1e-400"}), "parameter 'E' = 1e-400 is out of range: allowed (0, inf)"));
  }

  TEST_CASE("cli: an --out folder that cannot be made or written in is bad input (exit 2, named)") {
    const std::string tmp = std::string(AMPLE_TEST_TMP) + "/cli_outdir";
    std::filesystem::remove_all(tmp);
    std::filesystem::create_directories(tmp);
    std::ofstream(tmp + "/afile") << "a file, not a folder\n";
    const std::string run = "compaction nelsy=4 lstps=1 E=1e6 --vtk 0 --quiet --out ";
    for (const std::string& out : {tmp + "/afile/sub", tmp + "/afile", std::string("/proc/x")}) {
      CAPTURE(out);
      std::string err;
      CHECK(runBinary(run + out, &err) == 2);
      CHECK(has(err, "--out " + out + ": cannot create the output folder ("));
    }
    CHECK(std::filesystem::is_regular_file(tmp + "/afile"));
    std::string err;  // a folder where no file can be made, even by root
    CHECK(runBinary(run + "/proc", &err) == 2);
    CHECK(has(err, "--out /proc: cannot write in the output folder ("));
    const std::string locked = tmp + "/locked";  // a folder without write permission
    std::filesystem::create_directories(locked);
    std::filesystem::permissions(locked, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
    if (::access(locked.c_str(), W_OK) == 0) {
      MESSAGE("running as root: a folder without write permission is still writable, not tested");
    } else {
      CHECK(runBinary(run + locked, &err) == 2);
      CHECK(has(err, "--out " + locked + ": cannot write in the output folder (Permission denied)"));
      CHECK(std::filesystem::is_empty(locked));
    }
    std::filesystem::permissions(locked, std::filesystem::perms::owner_all);
    std::filesystem::remove_all(tmp);
  }
}
