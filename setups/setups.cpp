//--------------------------------------------------------------------------
// setups.cpp — the explicit table of setups and the parameter helpers
//--------------------------------------------------------------------------
// To add a problem: write setups/<name>.cpp with its params() and
// setupGrid(), declare them in setups/setupList.h and add one line below.
//--------------------------------------------------------------------------
#include "setups.h"
#include "ample/errors.h"
#include "setupList.h"
#include <cmath>
#include <sstream>

namespace ample {

const std::vector<Setup>& setupsTable() {
  static const std::vector<Setup> table = {
      {"compaction", "elastic column compacting under self weight (seed 002 sec 5.1)",
       compaction::params, compaction::setupGrid, compaction::results},
      {"beam", "large-deflection elastic cantilever with a tip load (seed 002 sec 5.2)",
       beam::params, beam::setupGrid, beam::results},
      {"collapse", "von Mises block collapsing under self weight (seed 002 sec 5.3)",
       collapse::params, collapse::setupGrid, collapse::results},
      {"shear", "simple shear of a unit square, elastic or von Mises (seed 000 sec 7.2)",
       shear::params, shear::setupGrid, shear::results},
      {"stretch", "plane-strain stretch of a von Mises block on a moving grid (seed 001 sec 3.1)",
       stretch::params, stretch::setupGrid, stretch::results},
  };
  return table;
}

const Setup* findSetup(const std::string& name) {
  for (const Setup& s : setupsTable())
    if (name == s.name) return &s;
  return nullptr;
}

double get(const Params& P, const std::string& name) {
  for (const Param& p : P)
    if (p.name == name) return p.value;
  throw InputError("internal: setup asked for unknown parameter '" + name + "'");
}

std::string rangeText(const Param& p) {
  auto num = [](double v) {
    if (std::isinf(v)) return std::string(v > 0 ? "inf" : "-inf");
    std::ostringstream s;
    s << v;
    return s.str();
  };
  std::string text = std::string(p.integer ? "integer in " : "") + (p.loOpen ? "(" : "[") +
                     num(p.lo) + ", " + num(p.hi) + (p.hiOpen ? ")" : "]");
  for (size_t k = 0; k < p.names.size(); ++k)
    text += (k ? ", " : " or by name: ") + num(p.lo + k) + " " + p.names[k];
  return text;
}

Params commonParams(int lstps) {
  const double inf = INFINITY;
  return {
      {"lstps", double(lstps), 1, 1e6, false, false, true, "number of equal load steps"},
      {"tol", 1e-9, 0, 1, true, true, false, "Newton-Raphson tolerance on fErr (eq 35)"},
      {"NRitMax", 10, 2, 1000, false, false, true, "most Newton-Raphson passes per load step"},
      {"substeps", 0, 0, 30, false, false, true,
       "remedy: halvings of a load step allowed when Newton fails (0 = the paper's algorithm)"},
      {"ghost", 0, 0, 1e3, false, false, false,
       "remedy: ghost-penalty factor gamma on the faces of the edge cells (0 = off, the paper's)"},
      {"mpType", 2, 1, 4, false, false, true, "material point type", {"MPM", "GIMP", "CPDI1", "CPDI2"}},
      {"mp", 2, 1, 20, false, false, true, "material points per cell in each direction"},
      {"cmType", 1, 1, 2, false, false, true, "constitutive model", {"elastic", "VM"}},
      {"formulation", 1, 1, 2, false, false, true,
       "equilibrium frame: updated or previously converged Lagrangian (seed 000)", {"UL", "PC"}},
      {"domainUpdate", 3, 0, 6, false, false, true, "GIMP domain update (seed 000 eqs 32-39)",
       {"none", "detF", "Fii", "Uii", "corner", "FiiVol", "FiiVolInc"}},
      {"E", 1.0, 0, inf, true, true, false, "Young's modulus (Pa)"},
      {"nu", 0.0, -1, 0.5, true, true, false, "Poisson's ratio"},
      {"rhoY", 20e3, 0, inf, true, true, false, "von Mises strength rho_y = sqrt(2 J2) at yield (Pa)"},
  };
}

void setDefault(Params& P, const std::string& name, double value) {
  for (Param& p : P)
    if (p.name == name) { p.value = value; return; }
  throw InputError("internal: setDefault of unknown parameter '" + name + "'");
}

}  // namespace ample
