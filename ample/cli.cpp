//--------------------------------------------------------------------------
// cli — the command line: which setup, its parameters, output options
//--------------------------------------------------------------------------
// See cli.h for the grammar, inputs and outputs.
//--------------------------------------------------------------------------
#include "cli.h"
#include "errors.h"
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace ample {

static double parseNumber(const std::string& name, const std::string& text) {
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v))
    throw InputError("parameter '" + name + "': '" + text + "' is not a finite number");
  return v;
}

static void setParam(Params& P, const std::string& name, const std::string& text,
                     const Setup& setup) {
  for (Param& p : P) {
    if (p.name != name) continue;
    double v = NAN;
    for (size_t k = 0; k < p.names.size(); ++k)  // a value given by name, e.g. mpType=CPDI2
      if (text == p.names[k]) v = p.lo + double(k);
    if (std::isnan(v)) v = parseNumber(name, text);
    const bool inRange = (p.loOpen ? v > p.lo : v >= p.lo) && (p.hiOpen ? v < p.hi : v <= p.hi);
    if (!inRange || (p.isInteger && v != std::floor(v)))
      throw InputError("parameter '" + name + "' = " + text + " is out of range: allowed " +
                       rangeText(p) + " (" + p.helpText + ")");
    p.value = v;
    return;
  }
  std::string names;
  for (const Param& p : P) names += " " + p.name;
  throw InputError("unknown parameter '" + name + "' for setup '" + setup.name +
                   "'; its parameters are:" + names);
}

CliRequest parseArgs(const std::vector<std::string>& args) {
  CliRequest req;
  if (args.empty()) throw InputError("no setup given\n" + usageText());
  if (args[0] == "--list") { req.mode = CliMode::List; return req; }
  if (args[0] == "--help" || args[0] == "-h") { req.mode = CliMode::Help; return req; }
  req.setup = findSetup(args[0]);
  if (!req.setup) throw InputError("unknown setup '" + args[0] + "'; known setups:\n" + listText());
  req.mode = CliMode::Run;
  req.params = req.setup->params();
  req.options.outDir = "output/" + args[0];
  for (size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    const bool hasValue = i + 1 < args.size();
    if (a == "--help" || a == "-h") { req.mode = CliMode::SetupHelp; return req; }
    if (a == "--quiet") { req.options.quiet = true; continue; }
    if (a == "--accept-floor") { req.options.acceptFloor = true; continue; }
    if (a == "--out") {
      if (!hasValue || args[i + 1].empty()) throw InputError("option '--out' needs a folder name");
      req.options.outDir = args[++i];
      continue;
    }
    if (a == "--vtk") {
      if (!hasValue) throw InputError("option '--vtk' needs a whole number N >= 0");
      const double v = parseNumber("--vtk", args[++i]);
      if (v < 0 || v != std::floor(v) || v > 1e9)
        throw InputError("option '--vtk' = " + args[i] + ": allowed a whole number in [0, 1e9]");
      req.options.vtkEvery = int(v);
      continue;
    }
    if (a == "--vtk-format") {
      const std::string v = hasValue ? args[++i] : "";
      if (v != "ascii" && v != "binary")
        throw InputError("option '--vtk-format'" + (hasValue ? " = '" + v + "'" : std::string()) +
                         ": allowed ascii (the default) or binary");
      req.options.vtkFormat = v == "binary" ? VtkFormat::Binary : VtkFormat::Ascii;
      continue;
    }
    const size_t eq = a.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("cannot read argument '" + a + "': expected name=value or an option "
                       "(--out DIR, --vtk N, --vtk-format F, --accept-floor, --quiet, --help)");
    setParam(req.params, a.substr(0, eq), a.substr(eq + 1), *req.setup);
  }
  return req;
}

std::string usageText() {
  return "usage: ample --list                 list the setups\n"
         "       ample --help                 this text\n"
         "       ample <setup> --help         the setup's parameters and defaults\n"
         "       ample <setup> [name=value ...] [--out DIR] [--vtk N] [--vtk-format F]\n"
         "                                    [--accept-floor] [--quiet]\n"
         "  --out DIR         output folder (default output/<setup>)\n"
         "  --vtk N           write mpData_<lstp>.vtk every N load steps (default 1, 0 = none)\n"
         "  --vtk-format F    ascii (default: text, 15 digits) or binary (legacy VTK BINARY:\n"
         "                    big-endian 4-byte floats and ints, smaller and faster to write)\n"
         "  --accept-floor    accept a load step whose residual stalled at its estimated\n"
         "                    round-off floor (said on stderr; off: such a step fails)\n"
         "  --quiet           no progress lines\n"
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
    s << "  " << p.name << " = " << p.value << "\t" << p.helpText << "; " << rangeText(p) << "\n";
  return s.str();
}

}  // namespace ample
