//--------------------------------------------------------------------------
// setups.h — the analyses the program knows, their parameters, and the table
//--------------------------------------------------------------------------
// [AMPLE] sec 4 (setupGrid). One problem = one file in setups/ with its
// parameter list and its setupGrid, plus one line in the table in
// setups/setups.cpp. Every parameter can be set on the command line
// (name=value); each carries its default, its valid range and a help line.
//--------------------------------------------------------------------------
#pragma once
#include "ample/analysis.h"
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace ample {

// One parameter of a setup, declared with a small builder that reads as its
// meaning, e.g.
//   Param("a", 2).integer(1, 64).help("grid refinement: h = 0.5 m / a")
//   Param("E", 1e6).above(0).help("Young's modulus (Pa)")          // (0, inf)
//   Param("mpType", 2).choice(1, {"MPM", "GIMP", "CPDI1", "CPDI2"})
// Without bounds a parameter takes any finite number.
struct Param {
  std::string name;
  double value = 0;                       // default, replaced by the command line
  double lo = -INFINITY, hi = INFINITY;   // valid range
  bool loOpen = true, hiOpen = true;      // true: the bound itself is excluded
  bool isInteger = false;                 // must be a whole number
  std::string helpText;                   // meaning and unit
  std::vector<std::string> names;         // optional names of the values lo, lo+1, ...

  Param(std::string name_, double value_) : name(std::move(name_)), value(value_) {}
  Param& atLeast(double v) { lo = v; loOpen = false; return *this; }    // [v, ...
  Param& above(double v) { lo = v; loOpen = true; return *this; }       // (v, ...
  Param& atMost(double v) { hi = v; hiOpen = false; return *this; }     // ..., v]
  Param& below(double v) { hi = v; hiOpen = true; return *this; }       // ..., v)
  Param& range(double l, double h) { return atLeast(l).atMost(h); }    // [l, h]
  Param& integer(double l, double h) { isInteger = true; return range(l, h); }  // whole, [l, h]
  Param& choice(int first, std::vector<std::string> valueNames) {       // first, first+1, ... by name
    names = std::move(valueNames);
    return integer(first, first + double(names.size()) - 1);
  }
  Param& help(std::string text) { helpText = std::move(text); return *this; }
};
using Params = std::vector<Param>;

double get(const Params& P, const std::string& name);  // value of a parameter
std::string rangeText(const Param& p);                 // e.g. "(0, inf)" or "integer in [1, 64]"

// the named figures of a run; a figure that is undefined for this run (e.g. a relative
// error with no load: 0 / 0) is NaN with its reason in `why`, and summary.json writes it as
// null with that reason ("results_undefined"), never as a bare nan or inf
struct Results : std::vector<std::pair<std::string, double>> {
  using vector::vector;
  std::vector<std::pair<std::string, std::string>> why;  // figure name -> why it is undefined
  void undefined(const std::string& name, const std::string& reason) { why.emplace_back(name, reason); }
};

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
