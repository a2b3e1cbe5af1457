//--------------------------------------------------------------------------
// setups.h — the analyses the program knows, their parameters, and the table
//--------------------------------------------------------------------------
// [AMPLE] sec 4 (setupGrid). One problem = one file in setups/ plus one line
// in the table in setups/setups.cpp. The file holds a plain struct of the
// setup's parameters with their defaults (deriving from Common, the ones every
// setup has), params(), which gives each member its name on the command line
// (name=value), its valid range and a help line, and setupGrid and results,
// which read the members (p.nelsy, p.E). params() is the one list of a setup's
// parameters: --help, the checks of the command line and summary.json read it.
//--------------------------------------------------------------------------
#pragma once
#include "ample/analysis.h"
#include "ample/errors.h"
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <utility>
#include <vector>

namespace ample {

// One parameter of a setup: its name, bound to a member of the setup's struct
// (param below), with its range and help, declared with a small builder that
// reads as its meaning, e.g.
//   param(P, "a", p.a).integer(1, 64).help("grid refinement: h = 0.5 m / a")
//   param(P, "E", p.E).above(0).help("Young's modulus (Pa)")          // (0, inf)
//   param(P, "mpType", p.mpType).choice(1, {"MPM", "GIMP", "CPDI1", "CPDI2"})
// Without bounds a parameter takes any finite number. Its kind: a number, a whole number
// (isInteger) or a choice (names).
struct Param {
  std::string name;
  double lo = -INFINITY, hi = INFINITY;   // valid range
  bool loOpen = true, hiOpen = true;      // true: the bound itself is excluded
  bool isInteger = false;                 // must be a whole number
  std::string helpText;                   // meaning and unit
  std::vector<std::string> names;         // optional names of the values lo, lo+1, ...
  std::function<double()> value;          // the member's value (its default until set)
  std::function<void(double)> set;        // sets the member (the command line, once checked)

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

// a setup's parameters in their order; from Setup::params it also owns the struct they are
// bound to (a fresh one, with the defaults). Moved, never copied: a copy would share that struct.
struct Params : std::vector<Param> {
  std::shared_ptr<void> values;                 // the setup's struct (Setup::params)
  const std::type_info* type = nullptr;         //   and its type
  Params() = default;
  Params(Params&&) = default;
  Params& operator=(Params&&) = default;
  Param& named(const std::string& name);        // the parameter of that name (InputError if none)
  const Param& named(const std::string& name) const;
};

// appends parameter `name`, bound to `member` (a double, int, bool or enum of the setup's struct,
// which must outlive P), and returns it for its range and help
template <class T>
Param& param(Params& P, std::string name, T& member) {
  Param p;
  p.name = std::move(name);
  p.value = [&member] {
    if constexpr (std::is_enum_v<T>) return double(int(member));
    else return double(member);
  };
  p.set = [&member](double v) {
    if constexpr (std::is_floating_point_v<T>) member = v;
    else member = T(int(v));                    // the command line has checked it is whole
  };
  P.push_back(std::move(p));
  return P.back();
}

void setParam(Params& P, const std::string& name, double value); // P.named(name).set(value)
std::string rangeText(const Param& p);                           // e.g. "(0, inf)" or "integer in [1, 64]"

// the parameters every setup has (load steps, Newton-Raphson settings, solver, remedies, point
// and material types, elastic constants, initial stress); their names, ranges and help:
// commonParams. A setup's struct derives from it and changes the defaults in its constructor.
struct Common {
  int lstps = 1;                                  // number of equal load steps
  double tol = 1e-9;                              // Newton-Raphson tolerance on fErr (eq 35)
  int NRitMax = 10;                               // most Newton-Raphson passes per load step
  LinearSolver solver = LinearSolver::LU;         // sparse solver of Kt(fd,fd)
  int substeps = 0;                               // remedies (docs/remedies.md), 0: off
  double ghost = 0, split = 0;
  int lone = 2;
  MpType mpType = MpType::GIMP;                   // material point type
  int mp = 2;                                     // points per cell in each direction
  CmType cmType = CmType::Elastic;                // constitutive model
  Formulation formulation = Formulation::UL;      // UL, PC or SS
  Locking locking = Locking::None;                // anti-locking
  DomainUpdate domainUpdate = DomainUpdate::Uii;  // GIMP domain update
  double E = 1.0, nu = 0.0, rhoY = 20e3;          // the points' mCst: Young's modulus (Pa), Poisson's
                                                  //   ratio, von Mises strength rho_y (Pa)
  bool geostatic = false;                         // start from the K0 stress of the weight
  double K0 = 1;
};
Params commonParams(Common& p);

// the named figures of a run; a figure that is undefined for this run (e.g. a relative
// error with no load: 0 / 0) is NaN with its reason in `why`, and summary.json writes it as
// null with that reason ("results_undefined"), never as a bare nan or inf
struct Results : std::vector<std::pair<std::string, double>> {
  using vector::vector;
  std::vector<std::pair<std::string, std::string>> why;  // figure name -> why it is undefined
  void undefined(const std::string& name, const std::string& reason) { why.emplace_back(name, reason); }
};

// the calls of a setup's line in the table, made in its file from its three functions on its
// own struct S:  SetupCalls calls() { return {params, setupGrid, results}; }
struct SetupCalls {
  std::function<Params()> params;                           // a fresh S with its defaults, bound
  std::function<Analysis(const Params&)> setupGrid;         // builds mesh and mpData
  std::function<Results(const Analysis&, const Params&)> results;  // figures of the final state

  template <class S>
  SetupCalls(Params (*table)(S&), Analysis (*grid)(const S&),
             Results (*figures)(const Analysis&, const S&)) {
    params = [table] {
      auto values = std::make_shared<S>();
      Params P = table(*values);
      P.values = values;
      P.type = &typeid(S);
      return P;
    };
    setupGrid = [grid](const Params& P) { return grid(valuesOf<S>(P)); };
    results = [figures](const Analysis& an, const Params& P) { return figures(an, valuesOf<S>(P)); };
  }
  template <class S>
  static const S& valuesOf(const Params& P) {
    if (!P.values || *P.type != typeid(S)) throw InputError("internal: a setup given another setup's parameters");
    return *static_cast<const S*>(P.values.get());
  }
};

struct Setup : SetupCalls {
  const char* name;
  const char* description;                    // one line for --list
  Setup(const char* name_, const char* description_, SetupCalls calls)
      : SetupCalls(std::move(calls)), name(name_), description(description_) {}
};

const std::vector<Setup>& setupsTable();
const Setup* findSetup(const std::string& name);

}  // namespace ample
