//--------------------------------------------------------------------------
// setups.h — the analyses the program knows, their parameters, and the table
//--------------------------------------------------------------------------
// Seed 002 sec 4 (setupGrid). One problem = one file in setups/ with its
// parameter list and its setupGrid, plus one line in the table in
// setups/setups.cpp. Every parameter can be set on the command line
// (name=value); each carries its default, its valid range and a help line.
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace ample {

struct Param {
  std::string name;
  double value;          // default, replaced by the command line
  double lo, hi;         // valid range
  bool loOpen, hiOpen;   // true: the bound itself is excluded
  bool integer;          // must be a whole number
  std::string help;      // meaning and unit
  std::vector<std::string> names = {};  // optional names of the values lo, lo+1, ...
};
using Params = std::vector<Param>;

double get(const Params& P, const std::string& name);  // value of a parameter
std::string rangeText(const Param& p);                 // e.g. "(0, inf)" or "integer in [1, 64]"

struct Analysis {
  Mesh mesh;                          // background grid with boundary conditions
  std::vector<MaterialPoint> mpData;  // material points
  int lstps = 1;                      // number of load steps
  double g = 0;                       // gravitational acceleration (m/s2), acting in -y
  double tol = 1e-9;                  // Newton-Raphson tolerance on fErr (eq 35)
  int NRitMax = 10;                   // most Newton-Raphson passes per load step
  int substeps = 0;                   // halvings of a failed load step allowed (0: none)
  double ghost = 0;                   // ghost-penalty factor of the edge cells (0: none)
  Formulation formulation = Formulation::UL;        // frame of equilibrium (seed 000)
  DomainUpdate domainUpdate = DomainUpdate::Uii;    // GIMP domain update (seed 002 eq 34)
  Eigen::VectorXd frct;                             // reactions of the last converged step
  // optional work of a setup at the start / end of each load step (nullptr: none),
  // e.g. a grid that follows the body, boundary cells that change, a reaction history
  std::function<void(Analysis& an, int lstp)> beforeStep, afterStep;
  std::vector<int> tagged;                          // points a setup marks for its hooks
  std::vector<std::vector<std::pair<std::string, double>>> history;  // rows for history.csv
};

using Results = std::vector<std::pair<std::string, double>>;  // named figures of a run

struct Setup {
  const char* name;
  const char* description;                    // one line for --list
  Params (*params)();                         // parameters with defaults and ranges
  Analysis (*setupGrid)(const Params&);       // builds mesh and mpData
  Results (*results)(const Analysis&, const Params&);  // figures of the final state
};

const std::vector<Setup>& setupsTable();
const Setup* findSetup(const std::string& name);

// parameters every setup has (load steps, Newton-Raphson settings, point and
// material types, elastic constants); a setup changes their defaults with setDefault
Params commonParams(int lstps);
void setDefault(Params& P, const std::string& name, double value);

}  // namespace ample
