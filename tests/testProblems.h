// testProblems.h — small problems built in code for the tests (not a test file itself)
#pragma once
#include "setups/program/run.h"
#include "ample/detMPs.h"
#include "ample/formulations/detMPsForm.h"
#include "ample/elemMPinfo.h"
#include "setups/formCoord2D.h"
#include "setups/setupHelpers.h"
#include "setups/setups.h"
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <random>
#include <string>

namespace ample::testing {

// a setup run in memory (no files) through all its load steps, with some parameters set;
// throws what solve throws when a step fails
// closed-form Cauchy stress (xx, yy) of Hencky elasticity (lambda, mu from E, nu) under
// the plane-strain stretch x = diag(lx, ly) X: sigma_i = (lam (e1 + e2) + 2 mu e_i) / J,
// e_i = ln l_i, J = lx ly (the patch tests' reference; shear 0)
inline Eigen::Vector2d henckyStretchStress(double lx, double ly, double E, double nu) {
  const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double e1 = std::log(lx), e2 = std::log(ly), J = lx * ly;
  return Eigen::Vector2d((lam * (e1 + e2) + 2 * mu * e1) / J, (lam * (e1 + e2) + 2 * mu * e2) / J);
}

// the largest stress error of the points against that stretch, relative to its largest entry
inline double stretchStressError(const std::vector<MaterialPoint>& mpData, const Eigen::Vector2d& sig) {
  double d = 0;
  for (const MaterialPoint& mp : mpData)
    d = std::max(d, std::max({std::abs(mp.sig(0) - sig(0)), std::abs(mp.sig(1) - sig(1)), std::abs(mp.sig(3))}) /
                        sig.cwiseAbs().maxCoeff());
  return d;
}

inline Analysis runSetup(const std::string& name,
                         const std::vector<std::pair<std::string, double>>& set, RunLog& log) {
  const Setup* s = findSetup(name);
  REQUIRE(s != nullptr);
  Params P = s->params();
  for (const auto& kv : set) setParam(P, kv.first, kv.second);
  Analysis an = s->setupGrid(P);
  solveRun(an, log);
  return an;
}

// a 4 x 4 grid of 1 m cells with an mp x mp block of points filling cells [1,3) x [1,3)
inline Analysis smallBlock(MpType mpType, CmType cmType, int mp = 2) {
  Common p;
  p.mp = mp;
  p.mpType = mpType;
  p.cmType = cmType;
  p.E = 1e6;
  p.nu = 0.3;
  p.rhoY = 2e3;
  Analysis an;
  an.mesh = formCoord2D(4, 4, 4.0, 4.0);
  fillBlock(an.mpData, Vector2d(1, 1), 2, 2, an.mesh.h, p, 1000.0);
  return an;
}

// give every point a converged, non-trivial state (Fn, epsEn) so that stress,
// geometric stiffness and (for von Mises) plastic flow all enter the tangent
inline void prestrain(std::vector<MaterialPoint>& mpData, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  for (MaterialPoint& mp : mpData) {
    mp.Fn << 1 + 0.05 * r(gen), 0.05 * r(gen), 0, 0.05 * r(gen), 1 + 0.05 * r(gen), 0, 0, 0, 1;
    mp.epsEn << 1e-3 * r(gen), 1e-3 * r(gen), 1e-3 * r(gen), 1e-3 * r(gen), 0, 0;
  }
}

// random displacement increment on the nodes linked to the points
inline Eigen::VectorXd randomUvw(const Analysis& an, double size, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  Eigen::VectorXd uvw = Eigen::VectorXd::Zero(an.mesh.nDoF());
  for (const MaterialPoint& mp : an.mpData)
    for (int v = 0; v < mp.nn; ++v)
      for (int i = 0; i < nD; ++i) uvw(dof(mp.nIN[v], i)) = size * r(gen);
  return uvw;
}

// relative difference |Kt - Kfd| / |Kt| between the assembled tangent and central
// differences of the assembled internal force, over the columns of the linked dofs
inline double tangentError(Analysis& an, const Eigen::VectorXd& uvw, Formulation form) {
  const Eigen::MatrixXd Kt = Eigen::MatrixXd(detMPsOf(uvw, an.mpData, form).Kt);
  Eigen::MatrixXd Kfd = Eigen::MatrixXd::Zero(Kt.rows(), Kt.cols());
  const double d = 1e-7;
  for (int c = 0; c < uvw.size(); ++c) {
    if (Kt.col(c).norm() == 0.0) continue;  // dof not linked to any point
    Eigen::VectorXd up = uvw, um = uvw;
    up(c) += d;
    um(c) -= d;
    Kfd.col(c) = (detMPsOf(up, an.mpData, form).fint - detMPsOf(um, an.mpData, form).fint) / (2 * d);
  }
  return (Kt - Kfd).norm() / Kt.norm();
}

// the whole text of a file ("" when it does not exist)
inline std::string fileText(const std::string& path) {
  std::ifstream f(path);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

// the point data of a legacy VTK file written by makeVtkMP, read by field name:
// "points" (x y z per point), and every SCALARS / VECTORS block under its own
// name (1 or 3 values per point), so fields added later do not disturb a reader
struct VtkPoints {
  int n = 0;
  std::map<std::string, std::vector<std::vector<double>>> field;  // name -> per point values
  const std::vector<double>& at(const std::string& name, int p) const { return field.at(name).at(p); }
  bool has(const std::string& name) const { return field.count(name) > 0; }
};
inline VtkPoints readVtkPoints(const std::string& path) {
  VtkPoints v;
  std::ifstream f(path);
  auto block = [&](const std::string& name, int width) {
    std::vector<std::vector<double>>& d = v.field[name];
    d.assign(v.n, std::vector<double>(width));
    for (int p = 0; p < v.n; ++p)
      for (int c = 0; c < width; ++c) f >> d[p][c];
  };
  for (std::string word; f >> word;) {
    std::string name, type, rest;
    if (word == "POINTS") {
      f >> v.n >> type;
      block("points", 3);
    } else if (word == "SCALARS") {
      int comps = 1;
      f >> name >> type;
      std::getline(f, rest);  // optional number of components
      int k = 0;
      if (std::stringstream(rest) >> k) comps = k;
      f >> word >> rest;       // LOOKUP_TABLE default
      block(name, comps);
    } else if (word == "VECTORS") {
      f >> name >> type;
      block(name, 3);
    }
  }
  return v;
}

// rows of a CSV file with a header line; columns by name
struct CsvTable {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;
  int col(const std::string& name) const {
    for (size_t c = 0; c < names.size(); ++c)
      if (names[c] == name) return int(c);
    return -1;
  }
  double at(size_t r, const std::string& name) const { return rows.at(r).at(size_t(col(name))); }
};
inline CsvTable readCsvTable(const std::string& path) {
  CsvTable t;
  std::ifstream f(path);
  std::string line;
  std::getline(f, line);
  std::stringstream h(line);
  for (std::string cell; std::getline(h, cell, ',');) t.names.push_back(cell);
  while (std::getline(f, line)) {
    if (line.empty()) continue;
    std::vector<double> row;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) row.push_back(std::stod(cell));
    t.rows.push_back(row);
  }
  return t;
}

}  // namespace ample::testing
