//--------------------------------------------------------------------------
// cli — the command line: which setup, its parameters, output options
//--------------------------------------------------------------------------
// See cli.h for the grammar, inputs and outputs.
//--------------------------------------------------------------------------
#include "ample/fast/detMPsFast.h"
#include "ample/fast/elemMPinfoFast.h"
#include "ample/solver/solverChoice.h"
#include "cli.h"
#include "ample/errors.h"
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>

namespace ample {

// digits from t[i] on (i moves past them); how many there were
static size_t skipDigits(const std::string& t, size_t& i) {
  const size_t from = i;
  while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]))) ++i;
  return i - from;
}

static void skipSign(const std::string& t, size_t& i) {
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
}

// a whole number as written: an optional sign and digits only (no point, no exponent)
static bool isWhole(const std::string& t) {
  size_t i = 0;
  skipSign(t, i);
  return skipDigits(t, i) > 0 && i == t.size();
}

// a plain decimal number: [sign] digits [. digits] [e|E [sign] digits], at least one digit
// before the exponent; no hex, inf, nan or spaces (which strtod would accept)
static bool isDecimal(const std::string& t) {
  size_t i = 0;
  skipSign(t, i);
  size_t digits = skipDigits(t, i);
  if (i < t.size() && t[i] == '.') digits += skipDigits(t, ++i);
  if (digits == 0) return false;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    skipSign(t, ++i);
    if (skipDigits(t, i) == 0) return false;
  }
  return i == t.size();
}

// a plain decimal number read as a double; any finite value (a subnormal too, or 0 when
// it underflows) is returned, only one that overflows to inf is refused
static double parseNumber(const std::string& name, const std::string& text) {
  if (!isDecimal(text))
    throw InputError("parameter '" + name + "': '" + text + "' is not a plain decimal number "
                     "(e.g. 20000, 2e4 or 0.3; no hex, inf, nan or spaces)");
  const double v = std::strtod(text.c_str(), nullptr);
  if (!std::isfinite(v))
    throw InputError("parameter '" + name + "': '" + text + "' overflows a double (not a finite number)");
  return v;
}

static std::string lowerCase(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// the number of a value given by name, e.g. mpType=CPDI2 or cpdi2 (any case); NAN if none
static double valueOfName(const Param& p, const std::string& text) {
  for (size_t k = 0; k < p.names.size(); ++k)
    if (lowerCase(text) == lowerCase(p.names[k])) return p.lo + double(k);
  return NAN;
}

// the value of text for parameter p: a name of p, or a number (whole if p is an integer)
static double valueOf(const Param& p, const std::string& text) {
  const double byName = valueOfName(p, text);
  if (!std::isnan(byName)) return byName;
  if (!p.names.empty() && !isDecimal(text)) {
    std::string allowed;
    for (size_t k = 0; k < p.names.size(); ++k)
      allowed += (k ? ", " : "") + std::to_string(int(p.lo) + int(k)) + " " + p.names[k];
    throw InputError("parameter '" + p.name + "' = '" + text + "': allowed " + allowed +
                     " (the number or the name, in any case)");
  }
  if (p.isInteger && !isWhole(text))
    throw InputError("parameter '" + p.name + "' = " + text + " is not a whole number: write it "
                     "with digits only (an optional sign, no point or exponent); allowed " +
                     rangeText(p) + " (" + p.helpText + ")");
  return parseNumber(p.name, text);
}

// name=text: the member of the parameter `name` set to the value of text, once checked
static void setFromText(Params& P, const std::string& name, const std::string& text,
                        const Setup& setup) {
  for (Param& p : P) {
    if (p.name != name) continue;
    const double v = valueOf(p, text);
    const bool inRange = (p.loOpen ? v > p.lo : v >= p.lo) && (p.hiOpen ? v < p.hi : v <= p.hi);
    if (!inRange)
      throw InputError("parameter '" + name + "' = " + text + " is out of range: allowed " +
                       rangeText(p) + " (" + p.helpText + ")");
    p.set(v);
    return;
  }
  std::string names;
  for (const Param& p : P) names += " " + p.name;
  throw InputError("unknown parameter '" + name + "' for setup '" + setup.name +
                   "'; its parameters are:" + names);
}

// the word after option args[i] (i moves on to it); refused when missing or another option
static std::string optionValue(const std::vector<std::string>& args, size_t& i, const std::string& needs) {
  const bool given = i + 1 < args.size() && args[i + 1].rfind("--", 0) != 0;
  if (!given)
    throw InputError("option '" + args[i] + "' needs " + needs +
                     (i + 1 < args.size() ? ", not the option '" + args[i + 1] + "'" : std::string()));
  return args[++i];
}

static int vtkEveryOf(const std::string& text) {
  const double v = isWhole(text) ? std::strtod(text.c_str(), nullptr) : -1;
  if (v < 0 || v > 1e9)
    throw InputError("option '--vtk' = '" + text + "': allowed a whole number in [0, 1e9]");
  return int(v);
}

static bool vtkGridEveryOf(const std::string& text) {
  if (text != "moved" && text != "every")
    throw InputError("option '--vtk-grid' = '" + text + "': allowed moved (the default) or every");
  return text == "every";
}

static VtkFormat vtkFormatOf(const std::string& text) {
  if (text != "ascii" && text != "binary")
    throw InputError("option '--vtk-format' = '" + text + "': allowed ascii (the default) or binary");
  return text == "binary" ? VtkFormat::Binary : VtkFormat::Ascii;
}

// the option args[i] and its value (i moves past it); false if args[i] is not an option;
// an option given twice is refused
static bool readOption(RunOptions& o, const std::vector<std::string>& args, size_t& i,
                       std::set<std::string>& seen) {
  static const std::set<std::string> known{"--quiet", "--accept-floor", "--out", "--vtk", "--vtk-format",
                                           "--vtk-grid"};
  const std::string a = args[i];
  if (!known.count(a)) return false;
  if (!seen.insert(a).second) throw InputError("option '" + a + "' is given twice; give it once");
  if (a == "--quiet") o.quiet = true;
  if (a == "--accept-floor") o.acceptFloor = true;
  if (a == "--out") o.outDir = optionValue(args, i, "a folder name");
  if (a == "--out" && o.outDir.empty()) throw InputError("option '--out' needs a folder name, not ''");
  if (a == "--vtk") o.vtkEvery = vtkEveryOf(optionValue(args, i, "a whole number N >= 0"));
  if (a == "--vtk-format")
    o.vtkFormat = vtkFormatOf(optionValue(args, i, "a value: allowed ascii (the default) or binary"));
  if (a == "--vtk-grid")
    o.vtkGridEvery = vtkGridEveryOf(optionValue(args, i, "a value: allowed moved (the default) or every"));
  return true;
}

// "--list", "--help" and "<setup> --help" (args[at]) stand alone: any other word is refused
static void standsAlone(const std::vector<std::string>& args, size_t at) {
  for (size_t i = at > 0 ? 1 : 0; i < args.size(); ++i)
    if (i != at)
      throw InputError("'" + args[at] + "' takes no other arguments" +
                       (at > 0 ? " than the setup" : "") + "; remove '" + args[i] + "'");
}

// name=value: the name given once, its value checked against its range
static void readParam(CliRequest& req, const std::string& a, std::map<std::string, std::string>& seen) {
  const size_t eq = a.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("cannot read argument '" + a + "': expected name=value or an option "
                     "(--out DIR, --vtk N, --vtk-format F, --vtk-grid G, --accept-floor, --quiet, --help)");
  const std::string name = a.substr(0, eq), text = a.substr(eq + 1);
  const auto earlier = seen.emplace(name, text);
  if (!earlier.second)
    throw InputError("parameter '" + name + "' is given twice (" + name + "=" + earlier.first->second +
                     ", then " + a + "); give it once");
  setFromText(req.params, name, text, *req.setup);
}

CliRequest parseArgs(const std::vector<std::string>& args) {
  CliRequest req;
  if (args.empty()) throw InputError("no setup given\n" + usageText());
  if (args[0] == "--list" || args[0] == "--help" || args[0] == "-h") {
    standsAlone(args, 0);
    req.mode = args[0] == "--list" ? CliMode::List : CliMode::Help;
    return req;
  }
  req.setup = findSetup(args[0]);
  if (!req.setup) throw InputError("unknown setup '" + args[0] + "'; known setups:\n" + listText());
  req.mode = CliMode::Run;
  req.params = req.setup->params();
  req.options.outDir = "output/" + args[0];
  req.options.basisLoop = elemMPinfoFast;                // large runs: the same numbers, faster
  req.options.pointLoop = detMPsFast;
  std::set<std::string> options;
  std::map<std::string, std::string> params;
  for (size_t i = 1; i < args.size(); ++i) {
    if (args[i] == "--help" || args[i] == "-h") {
      standsAlone(args, i);
      req.mode = CliMode::SetupHelp;
      return req;
    }
    if (!readOption(req.options, args, i, options)) readParam(req, args[i], params);
  }
  return req;
}

std::string usageText() {
  return "usage: ample --list                 list the setups\n"
         "       ample --help                 this text\n"
         "       ample <setup> --help         the setup's parameters and defaults\n"
         "       ample <setup> [name=value ...] [--out DIR] [--vtk N] [--vtk-format F]\n"
         "                                    [--vtk-grid G] [--accept-floor] [--quiet]\n"
         "  --out DIR         output folder (default output/<setup>)\n"
         "  --vtk N           write mpData_<lstp>.vtk every N load steps (default 1, 0 = none)\n"
         "  --vtk-format F    ascii (default: text, 15 digits) or binary (legacy VTK BINARY:\n"
         "                    big-endian 4-byte floats and ints, smaller and faster to write)\n"
         "  --vtk-grid G      moved (default): mesh.vtk once, and mesh_<lstp>.vtk (the grid\n"
         "                    with its nodal displacements) with each mpData file only\n"
         "                    when the grid moves (fem=1, stretch, doughnut); every: always\n"
         "  --accept-floor    accept a load step whose residual stalled at its estimated\n"
         "                    round-off floor (said on stderr; off: such a step fails)\n"
         "  --quiet           no progress lines\n"
         "values: plain decimal numbers (E=2e4, nu=0.3); whole numbers in digits only (lstps=40);\n"
         "  choices by number or name, in any case (mpType=cpdi2); each name and option once\n"
         "exit status: 0 converged, 1 a load step did not converge, 2 bad input\n"
         "units: SI (m, N, Pa, kg/m3, m/s2); tension positive; gravity acts in -y\n";
}

std::string listText() {
  std::ostringstream s;
  for (const Setup& st : setupsTable()) s << "  " << st.name << "\t" << st.description << "\n";
  return s.str();
}

std::string setupHelpText(const Setup& setup) {
  std::ostringstream s;
  s << setup.name << ": " << setup.description << "\nparameters (name=value):\n";
  for (const Param& p : setup.params())
    s << "  " << p.name << " = " << p.value() << "\t" << p.helpText << "; " << rangeText(p) << "\n";
  s << "solver= choices this build has: " << solversBuilt() << "\n";
  return s.str();
}

}  // namespace ample
