// Tests of the output (postPro, makeVtk, makeVtkMP, writeOutput): files
// written by a short run are read back and compared with the state in memory.
#include "ample/ample.h"
#include "testProblems.h"
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>

using namespace ample;

namespace {
std::vector<std::vector<double>> readCsv(const std::string& path, std::string& header) {
  std::ifstream f(path);
  std::getline(f, header);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(f, line);) {
    std::vector<double> row;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

// von Mises radius rho = sqrt(2 J2) = sqrt(s:s) of a stress [xx yy zz xy yz zx], s its
// deviator, the tensor shear components counted twice (written here, not taken from the code)
double rhoOfSix(double xx, double yy, double zz, double xy, double yz, double zx) {
  const double p = (xx + yy + zz) / 3;
  return std::sqrt((xx - p) * (xx - p) + (yy - p) * (yy - p) + (zz - p) * (zz - p) +
                   2 * (xy * xy + yz * yz + zx * zx));
}

// every point field of mpData_<lstp>.vtk against the same quantity from mp_final.csv:
// positions, displacement = x - X, the stresses by name, von Mises from the six stresses,
// volume, domain half lengths. The VTK is written with 15 digits: tolerance 1e-12 of the
// largest magnitude of the field. Fields are found by name, so added fields do not matter.
void checkVtkAgainstCsv(const std::string& vtkPath, const std::string& csvPath) {
  const testing::VtkPoints v = testing::readVtkPoints(vtkPath);
  const testing::CsvTable mp = testing::readCsvTable(csvPath);
  REQUIRE(v.n == int(mp.rows.size()));
  REQUIRE(v.n > 0);
  auto same = [&](const std::string& field, int comp, const std::function<double(size_t)>& csv) {
    CAPTURE(field);
    REQUIRE(v.has(field));
    double scale = 0;
    for (int p = 0; p < v.n; ++p) scale = std::max(scale, std::abs(csv(size_t(p))));
    for (int p = 0; p < v.n; ++p) {
      CAPTURE(p);
      CHECK(std::abs(v.at(field, p)[size_t(comp)] - csv(size_t(p))) <= 1e-12 * scale + 1e-300);
    }
  };
  auto col = [&](const char* name) { return [&mp, name](size_t r) { return mp.at(r, name); }; };
  same("points", 0, col("x"));
  same("points", 1, col("y"));
  same("displacement", 0, [&](size_t r) { return mp.at(r, "x") - mp.at(r, "X0"); });
  same("displacement", 1, [&](size_t r) { return mp.at(r, "y") - mp.at(r, "Y0"); });
  const std::vector<std::pair<std::string, std::string>> stresses = {
      {"sigma_xx", "sxx"}, {"sigma_yy", "syy"}, {"sigma_zz", "szz"},
      {"sigma_xy", "sxy"}, {"sigma_yz", "syz"}, {"sigma_zx", "szx"}};
  int found = 0;
  for (const auto& s : stresses)
    if (v.has(s.first)) {
      ++found;
      same(s.first, 0, col(s.second.c_str()));
    }
  CHECK(found >= 4);  // at least the in-plane ones and sigma_zz
  same("rho_vonMises", 0, [&](size_t r) {
    return rhoOfSix(mp.at(r, "sxx"), mp.at(r, "syy"), mp.at(r, "szz"), mp.at(r, "sxy"),
                    mp.at(r, "syz"), mp.at(r, "szx"));
  });
  same("volume", 0, col("V"));
  same("lpx", 0, col("lpx"));
  same("lpy", 0, col("lpy"));
}
}  // namespace

TEST_SUITE("output") {
  TEST_CASE("output: CSV / JSON and VTK of a compaction run read back") {
    const std::string dir = std::string(AMPLE_TEST_TMP) + "/output_compaction";
    const Setup* s = findSetup("compaction");
    Params P = s->params();
    setDefault(P, "nelsy", 4);
    setDefault(P, "lstps", 2);
    setDefault(P, "E", 1e6);  // stiff enough for two load steps
    RunOptions opt{dir, 1, true};
    REQUIRE(ample::ample(*s, P, opt) == 0);

    std::string header;
    const auto mp = readCsv(dir + "/mp_final.csv", header);
    CHECK(header == "X0,Y0,x,y,V0,V,sxx,syy,szz,sxy,syz,szx,lpx,lpy");
    REQUIRE(mp.size() == 16);  // 4 cells x 2 x 2 points
    double V0 = 0, weightOnBase = 0;
    for (const auto& r : mp) {
      REQUIRE(r.size() == 14);
      CHECK(r[0] == doctest::Approx(r[2]).epsilon(1e-12));     // rollers: no sideways motion
      CHECK(r[3] < r[1]);                                      // every point moves down
      V0 += r[4];
      weightOnBase += r[4] * 80 * 10;
    }
    CHECK(V0 == doctest::Approx(50 * 12.5).epsilon(1e-12));    // column 50 m x 12.5 m
    const auto steps = readCsv(dir + "/steps.csv", header);
    CHECK(header == "lstp,load_factor,NRit,fErr,converged,seconds");
    REQUIRE(steps.size() == 2);
    CHECK(steps[1][1] == doctest::Approx(1.0));
    CHECK(steps[1][3] <= 1e-9);
    const auto res = readCsv(dir + "/residuals.csv", header);
    int passes = 0;
    for (const auto& r : res) passes += r[0] == 2;
    CHECK(passes == int(steps[1][2]));                         // one row per pass

    const std::string vtk = testing::fileText(dir + "/mpData_2.vtk");
    CHECK(vtk.rfind("# vtk DataFile Version 2.0", 0) == 0);
    std::stringstream v(vtk.substr(vtk.find("POINTS")));
    std::string word, type;
    int n;
    v >> word >> n >> type;
    REQUIRE(n == 16);
    for (int p = 0; p < n; ++p) {
      double x, y, z;
      v >> x >> y >> z;
      CHECK(x == doctest::Approx(mp[p][2]).epsilon(1e-13));
      CHECK(y == doctest::Approx(mp[p][3]).epsilon(1e-13));
    }
    CHECK(testing::fileText(dir + "/mesh.vtk").find("CELLS 4 20") != std::string::npos);
    const std::string json = testing::fileText(dir + "/summary.json");
    CHECK(json.find("\"converged\": true") != std::string::npos);
    CHECK(json.find("\"nmp\": 16") != std::string::npos);
    CHECK(json.find("\"error\": ") != std::string::npos);
    CHECK(weightOnBase == doctest::Approx(80 * 10 * 50 * 12.5));
  }

  TEST_CASE("output: --vtk 0 writes no VTK / and a rerun removes the old step files") {
    const std::string dir = std::string(AMPLE_TEST_TMP) + "/output_novtk";
    const Setup* s = findSetup("compaction");
    Params P = s->params();
    setDefault(P, "nelsy", 4);
    setDefault(P, "lstps", 3);
    setDefault(P, "E", 1e6);
    REQUIRE(ample::ample(*s, P, RunOptions{dir, 1, true}) == 0);
    CHECK(std::filesystem::exists(dir + "/mpData_3.vtk"));
    setDefault(P, "lstps", 2);
    REQUIRE(ample::ample(*s, P, RunOptions{dir, 0, true}) == 0);
    CHECK(!std::filesystem::exists(dir + "/mpData_3.vtk"));
    CHECK(!std::filesystem::exists(dir + "/mesh.vtk"));
    CHECK(std::filesystem::exists(dir + "/summary.json"));
  }

  TEST_CASE("output: a load step that does not converge stops the run with status 1") {
    const std::string dir = std::string(AMPLE_TEST_TMP) + "/output_fail";
    const Setup* s = findSetup("collapse");
    Params P = s->params();
    setDefault(P, "lstps", 2);
    setDefault(P, "NRitMax", 2);  // too few passes to reach 1e-9
    CHECK(ample::ample(*s, P, RunOptions{dir, 1, true}) == 1);
    const std::string json = testing::fileText(dir + "/summary.json");
    CHECK(json.find("\"converged\": false") != std::string::npos);
    CHECK(json.find("\"last_converged_step\": 0") != std::string::npos);
    CHECK(json.find("load step 1 did not converge") != std::string::npos);
    CHECK(!std::filesystem::exists(dir + "/mpData_1.vtk"));
  }
  TEST_CASE("output: every point field of the last mpData VTK equals mp_final.csv (beam and collapse)") {
    // the beam bends (sigma_xy and sigma_zz = nu (sigma_xx + sigma_yy) non-zero, all
    // different); the collapse flows plastically under gravity
    for (const auto& run : std::vector<std::pair<std::string, std::vector<std::pair<std::string, double>>>>{
             {"beam", {{"a", 1}, {"mp", 2}, {"lstps", 3}, {"P", 10e3}}}, {"collapse", {{"a", 1}, {"mp", 2}, {"lstps", 4}}}}) {
      CAPTURE(run.first);
      const std::string dir = std::string(AMPLE_TEST_TMP) + "/output_vtk_" + run.first;
      const Setup* s = findSetup(run.first);
      Params P = s->params();
      for (const auto& kv : run.second) setDefault(P, kv.first, kv.second);
      REQUIRE(ample::ample(*s, P, RunOptions{dir, 1, true}) == 0);
      const int last = int(get(P, "lstps"));
      const testing::CsvTable mp = testing::readCsvTable(dir + "/mp_final.csv");
      double sxy = 0, szz = 0;  // the run must exercise the shear and the out-of-plane stress
      for (size_t r = 0; r < mp.rows.size(); ++r) {
        sxy = std::max(sxy, std::abs(mp.at(r, "sxy")));
        szz = std::max(szz, std::abs(mp.at(r, "szz")));
      }
      CHECK(sxy > 0);
      CHECK(szz > 0);
      checkVtkAgainstCsv(dir + "/mpData_" + std::to_string(last) + ".vtk", dir + "/mp_final.csv");
    }
  }
  TEST_CASE("output: after a failed load step mp_final.csv holds the Cauchy stress of the last converged step (restoreConverged)") {
    // collapse, h = 2 m, 2 x 2 points, NRitMax = 4: steps 1-16 converge, step 17 does not.
    // restoreConverged rebuilds sigma = tau(epsE_n) / det(F_n) from the stored state; the
    // points have changed volume by up to 1.7 % (det F_n = V / V0), so storing the
    // Kirchhoff stress instead would differ from the VTK of step 16 by that much, far
    // beyond the 1e-12 of the comparison.
    const std::string dir = std::string(AMPLE_TEST_TMP) + "/output_restore";
    const Setup* s = findSetup("collapse");
    Params P = s->params();
    setDefault(P, "a", 1);
    setDefault(P, "mp", 2);
    setDefault(P, "NRitMax", 4);
    REQUIRE(ample::ample(*s, P, RunOptions{dir, 1, true}) == 1);
    const std::string json = testing::fileText(dir + "/summary.json");
    const size_t at = json.find("\"last_converged_step\": ");
    REQUIRE(at != std::string::npos);
    const int last = std::stoi(json.substr(at + 23));
    CHECK(last == 16);
    REQUIRE(last >= 1);
    CHECK(!std::filesystem::exists(dir + "/mpData_" + std::to_string(last + 1) + ".vtk"));
    const testing::CsvTable mp = testing::readCsvTable(dir + "/mp_final.csv");
    double Jmin = 1;
    for (size_t r = 0; r < mp.rows.size(); ++r) Jmin = std::min(Jmin, mp.at(r, "V") / mp.at(r, "V0"));
    CHECK(Jmin < 0.99);  // J != 1: Kirchhoff and Cauchy stress differ
    checkVtkAgainstCsv(dir + "/mpData_" + std::to_string(last) + ".vtk", dir + "/mp_final.csv");
  }
}

namespace {
// the numbers that follow `key` in a legacy VTK file (a POINTS block or a field), n x k of them
std::vector<double> vtkBlock(const std::string& vtk, const std::string& key, int count) {
  const size_t at = vtk.find(key);
  REQUIRE(at != std::string::npos);
  std::stringstream s(vtk.substr(at));
  std::string line;
  std::getline(s, line);                                   // the key line
  if (key.rfind("SCALARS", 0) == 0) std::getline(s, line);  // LOOKUP_TABLE default
  std::vector<double> v(count);
  for (double& x : v) s >> x;
  return v;
}
}  // namespace

// issue 10 item 6: the grid of each output step with its nodal displacements, as AMPLE
// writes it; a grid that moves (the stretch) as it is in that step; all six stresses and
// the displacement components of the points as scalars
TEST_SUITE("output") {
  TEST_CASE("output: mesh_<lstp>.vtk holds the grid of that step and its nodal displacements") {
    const std::string dir = std::string(AMPLE_TEST_TMP) + "/output_stretch";
    const Setup* s = findSetup("stretch");
    Params P = s->params();
    setDefault(P, "lstps", 5);
    REQUIRE(ample::ample(*s, P, RunOptions{dir, 1, true}) == 0);
    for (int lstp : {1, 5}) {
      CAPTURE(lstp);
      const std::string vtk = testing::fileText(dir + "/mesh_" + std::to_string(lstp) + ".vtk");
      const std::vector<double> x = vtkBlock(vtk, "POINTS 9 double", 27);   // 3 x 3 nodes
      const std::vector<double> u = vtkBlock(vtk, "VECTORS displacement double", 27);
      const double L = 2.0 + (lstp - 1) * 0.2;             // the grid spans the body at the step's start
      double xMax = 0;
      for (int n = 0; n < 9; ++n) xMax = std::max(xMax, x[3 * n]);
      CHECK(xMax == doctest::Approx(L).epsilon(1e-14));
      for (int n = 0; n < 9; ++n) {
        if (x[3 * n] > L - 1e-9) CHECK(u[3 * n] == doctest::Approx(0.2).epsilon(1e-14));  // pulled side
        if (x[3 * n] < 1e-9) CHECK(u[3 * n] == 0.0);                                        // roller
        if (x[3 * n + 1] < 1e-9) CHECK(u[3 * n + 1] == 0.0);                                // base
      }
    }
    const std::string mp = testing::fileText(dir + "/mpData_5.vtk");
    for (const char* f : {"sigma_xx", "sigma_yy", "sigma_zz", "sigma_xy", "sigma_yz", "sigma_zx", "ux", "uy"})
      CHECK(mp.find(std::string("SCALARS ") + f + " double 1") != std::string::npos);
  }
}

// issue 10 item 6: at pass 0 the reactions of the step are not known; with fext = 0 (a
// displacement-driven step) eq 35 divided by |0 + 0| + eps: 5.4e17 at step 7 of the stretch
TEST_SUITE("output") {
  TEST_CASE("output: the pass-0 residual of a displacement-driven step is of order one") {
    const Setup* s = findSetup("stretch");
    const Params P = s->params();
    Analysis an = s->setupGrid(P);
    RunLog log;
    solve(an, log);
    int rows = 0;
    for (const ResidualRow& r : log.residuals)
      if (r.NRit == 0 && r.lstp > 1) {                     // step 1 starts unstressed: 0
        CHECK(r.fErr < 10.0);
        ++rows;
      }
    CHECK(rows == 19);
  }
}
