// Tests of the command line (cli.cpp, main.cpp): parameters parsed and
// checked, bad input refused with exit status 2 and no output written.
#include "ample/cli.h"
#include "ample/errors.h"
#include <doctest/doctest.h>
#include <cstdlib>
#include <random>
#include <filesystem>
#include <sys/wait.h>

using namespace ample;

namespace {
int runBinary(const std::string& args) {
  const std::string cmd = std::string(AMPLE_BINARY) + " " + args + " >/dev/null 2>&1";
  const int st = std::system(cmd.c_str());
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}
}  // namespace

TEST_SUITE("cli") {
  TEST_CASE("cli: parameters override the setup defaults") {
    const CliRequest r = parseArgs({"compaction", "nelsy=8", "E=2e4", "--vtk", "5", "--quiet",
                                    "--out", "x/y"});
    REQUIRE(r.mode == CliMode::Run);
    CHECK(get(r.params, "nelsy") == 8);
    CHECK(get(r.params, "E") == 2e4);
    CHECK(get(r.params, "nu") == 0.0);  // untouched default
    CHECK(r.options.vtkEvery == 5);
    CHECK(r.options.quiet);
    CHECK(r.options.outDir == "x/y");
    CHECK(parseArgs({"beam"}).options.outDir == "output/beam");
    const CliRequest n = parseArgs({"collapse", "mpType=CPDI2", "formulation=PC", "domainUpdate=corner"});
    CHECK(get(n.params, "mpType") == 4);  // values may be given by name
    CHECK(get(n.params, "formulation") == 2);
    CHECK(get(n.params, "domainUpdate") == 4);
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

  TEST_CASE("cli: the program exits 2 on bad input and writes nothing") {
    const std::string dir = std::string(AMPLE_TEST_TMP) + "/cli_bad";
    std::filesystem::remove_all(dir);
    CHECK(runBinary("compaction E=-5 --out " + dir) == 2);
    CHECK(runBinary("nosuchsetup --out " + dir) == 2);
    CHECK(runBinary("compaction mp=1.5 --out " + dir) == 2);
    CHECK(!std::filesystem::exists(dir));
    CHECK(runBinary("--list") == 0);
    CHECK(runBinary("collapse --help") == 0);
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
    int parsed = 0, refused = 0;
    for (int trial = 0; trial < 20000; ++trial) {
      std::vector<std::string> args;
      for (int k = len(gen); k > 0; --k) {
        std::string w = words[pick(gen)];
        if (gen() % 5 == 0) w += char(byte(gen));   // a random byte appended
        if (gen() % 7 == 0 && !w.empty()) w[gen() % w.size()] = char(byte(gen));
        args.push_back(w);
      }
      try {
        parseArgs(args);
        ++parsed;
      } catch (const InputError&) {
        ++refused;  // the only exception allowed
      }
    }
    CHECK(parsed + refused == 20000);
    CHECK(parsed > 0);
    CHECK(refused > 0);
  }
}
