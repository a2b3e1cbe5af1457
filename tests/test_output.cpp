// Tests of the output (postPro, makeVtk, makeVtkMP, makeVtkWriter, writeOutput): files
// written by a short run are read back and compared with the state in memory.
#include "setups/program/run.h"
#include "testProblems.h"
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
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
    setParam(P, "nelsy", 4);
    setParam(P, "lstps", 2);
    setParam(P, "E", 1e6);  // stiff enough for two load steps
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

  TEST_CASE("output: summary.json counts the sparse solve's symbolic analyses (one per pattern) and LU fallbacks") {
    // one load step: one pattern of Kt(fd,fd), so exactly one analysis; three steps: at least
    // one, at most one a step; an elastic, symmetric Kt: LDLT never hands a pass to SparseLU
    const std::string dir = std::string(AMPLE_TEST_TMP) + "/output_solver_counts";
    const Setup* s = findSetup("compaction");
    for (int lstps : {1, 3}) {
      Params P = s->params();
      setParam(P, "nelsy", 4);
      setParam(P, "lstps", lstps);
      setParam(P, "E", 1e6);
      setParam(P, "solver", 1);                     // LDLT
      REQUIRE(ample::ample(*s, P, RunOptions{dir, 0, true}) == 0);
      const std::string json = testing::fileText(dir + "/summary.json");
      const size_t a = json.find("\"solver_analyses\": "), f = json.find("\"lu_fallbacks\": ");
      REQUIRE(a != std::string::npos);
      REQUIRE(f != std::string::npos);
      const int analyses = std::atoi(json.c_str() + a + 19), fallbacks = std::atoi(json.c_str() + f + 16);
      CAPTURE(lstps);
      CHECK(analyses >= 1);
      CHECK(analyses <= lstps);
      if (lstps == 1) CHECK(analyses == 1);
      CHECK(fallbacks == 0);
    }
  }

  TEST_CASE("output: --vtk 0 writes no VTK / and a rerun removes the old step files") {
    const std::string dir = std::string(AMPLE_TEST_TMP) + "/output_novtk";
    const Setup* s = findSetup("compaction");
    Params P = s->params();
    setParam(P, "nelsy", 4);
    setParam(P, "lstps", 3);
    setParam(P, "E", 1e6);
    REQUIRE(ample::ample(*s, P, RunOptions{dir, 1, true}) == 0);
    CHECK(std::filesystem::exists(dir + "/mpData_3.vtk"));
    setParam(P, "lstps", 2);
    REQUIRE(ample::ample(*s, P, RunOptions{dir, 0, true}) == 0);
    CHECK(!std::filesystem::exists(dir + "/mpData_3.vtk"));
    CHECK(!std::filesystem::exists(dir + "/mesh.vtk"));
    CHECK(std::filesystem::exists(dir + "/summary.json"));
  }

  TEST_CASE("output: a load step that does not converge stops the run with status 1") {
    const std::string dir = std::string(AMPLE_TEST_TMP) + "/output_fail";
    const Setup* s = findSetup("collapse");
    Params P = s->params();
    setParam(P, "lstps", 2);
    setParam(P, "NRitMax", 2);  // too few passes to reach 1e-9
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
      for (const auto& kv : run.second) setParam(P, kv.first, kv.second);
      REQUIRE(ample::ample(*s, P, RunOptions{dir, 1, true}) == 0);
      const int last = int(P.named("lstps").value());
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
    setParam(P, "a", 1);
    setParam(P, "mp", 2);
    setParam(P, "NRitMax", 4);
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

// the grid of each output step with its nodal displacements, as AMPLE
// writes it; a grid that moves (the stretch) as it is in that step; all six stresses and
// the displacement components of the points as scalars
TEST_SUITE("output") {
  TEST_CASE("output: mesh_<lstp>.vtk holds the grid of that step and its nodal displacements") {
    const std::string dir = std::string(AMPLE_TEST_TMP) + "/output_stretch";
    const Setup* s = findSetup("stretch");
    Params P = s->params();
    setParam(P, "lstps", 5);
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

// at pass 0 the reactions of the step are not known; with fext = 0 (a
// displacement-driven step) eq 35 divided by |0 + 0| + eps: 5.4e17 at step 7 of the stretch
TEST_SUITE("output") {
  TEST_CASE("output: the pass-0 residual of a displacement-driven step is of order one") {
    const Setup* s = findSetup("stretch");
    const Params P = s->params();
    Analysis an = s->setupGrid(P);
    RunLog log;
    solveRun(an, log);
    int rows = 0;
    for (const ResidualRow& r : log.residuals)
      if (r.NRit == 0 && r.lstp > 1) {                     // step 1 starts unstressed: 0
        CHECK(r.fErr < 10.0);
        ++rows;
      }
    CHECK(rows == 19);
  }
}

// --vtk-format binary. Both formats of the same run are read by one reader written
// here from the legacy format (VTK file formats, "Simple Legacy Formats"): four header lines,
// then keyword lines, each followed by its numbers: in ASCII as text, in BINARY as big-endian
// 4-byte IEEE floats / int32 with one "\n" after the block.
namespace {
struct VtkSection {
  std::string keyword;              // the keyword line, e.g. "POINTS 16 float"
  std::vector<double> reals;
  std::vector<long> ints;
};
struct VtkFile {
  std::vector<std::string> header;  // the four header lines
  std::vector<VtkSection> sections;
  size_t bytes = 0;                 // the file's size
  size_t consumed = 0;              // the bytes the reader used: must be all of them
};

VtkFile readLegacyVtk(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  size_t pos = 0;
  auto line = [&]() {
    const size_t end = b.find('\n', pos);
    REQUIRE(end != std::string::npos);
    const std::string l = b.substr(pos, end - pos);
    pos = end + 1;
    return l;
  };
  VtkFile f;
  f.bytes = b.size();
  for (int k = 0; k < 4; ++k) f.header.push_back(line());
  const bool binary = f.header[2] == "BINARY";
  auto word32 = [&]() {               // big-endian: the most significant byte first
    REQUIRE(pos + 4 <= b.size());
    std::uint32_t u = 0;
    for (int k = 0; k < 4; ++k) u = (u << 8) | std::uint32_t(static_cast<unsigned char>(b[pos++]));
    return u;
  };
  auto text = [&]() {                 // the next number of an ASCII block
    while (pos < b.size() && (b[pos] == ' ' || b[pos] == '\n')) ++pos;
    const size_t end = b.find_first_of(" \n", pos);
    REQUIRE(end != std::string::npos);
    const std::string t = b.substr(pos, end - pos);
    pos = end;
    return t;
  };
  long nPointData = 0;
  while (pos < b.size()) {
    VtkSection s;
    s.keyword = line();
    std::istringstream w(s.keyword);
    std::string key;
    long n = 0, size = 0, reals = 0, ints = 0;
    w >> key;
    if (key == "POINTS") { w >> n; reals = 3 * n; }
    else if (key == "CELLS") { w >> n >> size; ints = size; }
    else if (key == "CELL_TYPES") { w >> n; ints = n; }
    else if (key == "POINT_DATA") { w >> nPointData; }
    else if (key == "VECTORS") { reals = 3 * nPointData; }
    else if (key == "SCALARS") { CHECK(line() == "LOOKUP_TABLE default"); reals = nPointData; }
    else FAIL("unexpected keyword line '" << s.keyword << "'");
    for (long k = 0; k < reals; ++k) {
      if (!binary) { s.reals.push_back(std::stod(text())); continue; }
      const std::uint32_t u = word32();
      float x;
      std::memcpy(&x, &u, 4);
      s.reals.push_back(x);
    }
    for (long k = 0; k < ints; ++k) s.ints.push_back(binary ? long(std::int32_t(word32())) : std::stol(text()));
    if (reals + ints > 0) {           // the block ends its line
      REQUIRE(pos < b.size());
      CHECK(b[pos] == '\n');
      ++pos;
    }
    f.sections.push_back(s);
  }
  f.consumed = pos;
  return f;
}

// the size the BINARY file must have for the sections of the ASCII one: the same lines with
// "float" for "double", and 4 bytes per number plus one "\n" per block
size_t binarySizeOf(const VtkFile& ascii) {
  size_t n = 0;
  for (size_t k = 0; k < 4; ++k) n += (k == 2 ? std::string("BINARY") : ascii.header[k]).size() + 1;
  for (const VtkSection& s : ascii.sections) {
    std::string kw = s.keyword;
    const size_t d = kw.find(" double");
    if (d != std::string::npos) kw.replace(d, 7, " float");
    n += kw.size() + 1;
    if (kw.rfind("SCALARS", 0) == 0) n += std::string("LOOKUP_TABLE default").size() + 1;
    const size_t numbers = s.reals.size() + s.ints.size();
    if (numbers > 0) n += 4 * numbers + 1;
  }
  return n;
}

// every section and every number of a BINARY file against the ASCII file of the same run.
// Reals: a float is the double rounded to nearest, relative error <= 2^-24 = 5.96e-8; the
// ASCII text has 15 digits (5e-15): tolerance 6e-8 |ascii| + 1e-44 (a float below 1.2e-38 is
// subnormal, absolute error <= 7e-46). Ints: equal.
void checkBinaryAgainstAscii(const std::string& binPath, const std::string& asciiPath) {
  CAPTURE(binPath);
  const VtkFile a = readLegacyVtk(asciiPath), b = readLegacyVtk(binPath);
  CHECK(a.header[2] == "ASCII");
  CHECK(b.header[0] == "# vtk DataFile Version 2.0");
  CHECK(b.header[1] == a.header[1]);
  CHECK(b.header[2] == "BINARY");
  CHECK(b.header[3] == "DATASET UNSTRUCTURED_GRID");
  CHECK(a.consumed == a.bytes);
  CHECK(b.consumed == b.bytes);                  // nothing left over, nothing missing
  CHECK(b.bytes == binarySizeOf(a));             // the exact size of the legacy layout
  REQUIRE(b.sections.size() == a.sections.size());
  for (size_t s = 0; s < a.sections.size(); ++s) {
    const VtkSection &sa = a.sections[s], &sb = b.sections[s];
    CAPTURE(sa.keyword);
    std::string kw = sa.keyword;
    if (kw.find(" double") != std::string::npos) kw.replace(kw.find(" double"), 7, " float");
    CHECK(sb.keyword == kw);
    REQUIRE(sb.reals.size() == sa.reals.size());
    REQUIRE(sb.ints.size() == sa.ints.size());
    int bad = 0;
    for (size_t k = 0; k < sa.reals.size(); ++k)
      bad += !(std::abs(sb.reals[k] - sa.reals[k]) <= 6e-8 * std::abs(sa.reals[k]) + 1e-44);
    for (size_t k = 0; k < sa.ints.size(); ++k) bad += sb.ints[k] != sa.ints[k];
    CHECK(bad == 0);
  }
}
}  // namespace

TEST_SUITE("output") {
  TEST_CASE("output: --vtk-format binary writes the same sections and values as ASCII, big-endian floats") {
    // the beam bends (every stress component and the displacements non-zero, all different);
    // mesh.vtk (no point data), mesh_<lstp>.vtk (nodal displacements), mpData_<lstp>.vtk
    const Setup* s = findSetup("beam");
    Params P = s->params();
    for (const auto& kv : std::vector<std::pair<std::string, double>>{{"a", 1}, {"mp", 2}, {"lstps", 3}, {"P", 10e3}})
      setParam(P, kv.first, kv.second);
    const std::string dirA = std::string(AMPLE_TEST_TMP) + "/output_vtk_ascii",
                      dirB = std::string(AMPLE_TEST_TMP) + "/output_vtk_binary";
    RunOptions opt{dirA, 1, true};
    opt.vtkGridEvery = true;                     // mesh_<lstp>.vtk of a grid that does not move
    REQUIRE(ample::ample(*s, P, opt) == 0);
    opt.outDir = dirB;
    opt.vtkFormat = VtkFormat::Binary;
    REQUIRE(ample::ample(*s, P, opt) == 0);
    for (const char* f : {"mesh.vtk", "mesh_1.vtk", "mesh_3.vtk", "mpData_1.vtk", "mpData_3.vtk"})
      checkBinaryAgainstAscii(dirB + "/" + f, dirA + "/" + f);
    // the saving is in the points' reals (15 digits against 4 bytes); the grid's small
    // integers and short coordinates ("4 0 1 24 23") are shorter as text: mesh.vtk grows
    const size_t a = readLegacyVtk(dirA + "/mpData_3.vtk").bytes, b = readLegacyVtk(dirB + "/mpData_3.vtk").bytes;
    CHECK(double(b) < 0.4 * double(a));
    const VtkFile mp = readLegacyVtk(dirB + "/mpData_3.vtk");
    CHECK(mp.sections.size() == 17);             // points, cells, types, point data, u, 12 scalars
    double sxy = 0;                              // the run exercises a shear stress
    for (const VtkSection& sec : mp.sections)
      if (sec.keyword == "SCALARS sigma_xy float 1")
        for (double v : sec.reals) sxy = std::max(sxy, std::abs(v));
    CHECK(sxy > 0);
  }
  TEST_CASE("output: the binary writer's bytes for known numbers (big-endian IEEE single, int32)") {
    // 1.0f = 0x3F800000, -2.5f = 0xC0200000, 0.1 -> 0x3DCCCCCD (rounded to nearest);
    // int 9 = 00 00 00 09, -1 = FF FF FF FF
    VtkWriter w(VtkFormat::Binary, "t", "UNSTRUCTURED_GRID");
    const size_t head = w.text().size();
    CHECK(head == std::string("# vtk DataFile Version 2.0\nt\nBINARY\nDATASET UNSTRUCTURED_GRID\n").size());
    w.reals({1.0, -2.5, 0.1}, 3);
    w.ints({9, -1}, 1);
    const std::string want("\x3F\x80\x00\x00\xC0\x20\x00\x00\x3D\xCC\xCC\xCD\n\x00\x00\x00\x09\xFF\xFF\xFF\xFF\n", 22);  // 3 x 4 + 1 + 2 x 4 + 1 bytes
    CHECK(w.text().substr(head) == want);
    CHECK(std::string(w.realType()) == "float");
    VtkWriter t(VtkFormat::Ascii, "t", "UNSTRUCTURED_GRID");
    t.reals({1.0, -2.5, 0.1}, 3);
    t.ints({9, -1}, 1);
    CHECK(t.text().substr(head - 1) == "1 -2.5 0.1\n9\n-1\n");  // "ASCII" is one byte shorter
    CHECK(std::string(t.realType()) == "double");
  }

  TEST_CASE("output: the ASCII reals are the text of printf %.15g (subnormal, -0, 1e300, 15 digits, integers)") {
    const std::vector<double> xs{0.0, -0.0, 1.0, -2.5, 0.1, 1.0 / 3.0, 123456789012345.0, 1234567890123456.0,
                                 1e300, -1e300, 1e-300, 4.9406564584124654e-324, 2.2250738585072009e-308,
                                 1.7976931348623157e308, 0.000123456789012345, 1e15, 1e16, 1e-5, 0.0001,
                                 100.0, -7.0, 2.0 / 3.0 * 1e-7, 9.99999999999999e14, 9.999999999999999e14};
    for (double x : xs) {
      char want[64];
      std::snprintf(want, sizeof want, "%.15g", x);     // the C library, not to_chars
      CAPTURE(want);
      CHECK(vtkReal(x) == std::string(want));
    }
    VtkWriter w(VtkFormat::Ascii, "t", "UNSTRUCTURED_GRID");
    const size_t head = w.text().size();
    w.reals(xs, 4);
    std::string want;
    for (size_t k = 0; k < xs.size(); ++k) {
      char b[64];
      std::snprintf(b, sizeof b, "%.15g%c", xs[k], (k + 1) % 4 == 0 ? '\n' : ' ');
      want += b;
    }
    CHECK(w.text().substr(head) == want);
  }

  TEST_CASE("output: a VTK file written in chunks smaller than it equals the text kept whole") {
    const std::string path = std::string(AMPLE_TEST_TMP) + "/output_chunked.vtk";
    std::vector<double> x(5000);
    for (size_t k = 0; k < x.size(); ++k) x[k] = std::sin(double(k)) * std::pow(10.0, double(k % 40) - 20);
    std::vector<int> n(3000);
    for (size_t k = 0; k < n.size(); ++k) n[k] = int(k * 7919 % 100003) - 50000;
    for (VtkFormat f : {VtkFormat::Ascii, VtkFormat::Binary}) {
      VtkWriter whole(f, "t", "UNSTRUCTURED_GRID"), chunked(f, "t", "UNSTRUCTURED_GRID", path, 1000);
      for (VtkWriter* w : {&whole, &chunked}) {
        w->line("POINTS 5000 x");
        w->reals(x, 3);
        w->line("CELLS");
        w->ints(n, 5);
      }
      CHECK(!std::filesystem::exists(path));               // only path.tmp until finish()
      CHECK(std::filesystem::file_size(path + ".tmp") <= whole.text().size());
      chunked.finish();
      CHECK(!std::filesystem::exists(path + ".tmp"));
      CHECK(whole.text().size() > 20 * 1000);              // many chunks
      CHECK(testing::fileText(path) == whole.text());
      std::filesystem::remove(path);
    }
    {                                                      // not finished: no file, no tmp left
      VtkWriter w(VtkFormat::Ascii, "t", "UNSTRUCTURED_GRID", path, 1000);
      w.reals(x, 3);
    }
    CHECK(!std::filesystem::exists(path));
    CHECK(!std::filesystem::exists(path + ".tmp"));
  }

  TEST_CASE("output: grid files written by default / in fem mode / with --vtk-grid every") {
    // a grid that stays put: mesh.vtk once; fem=1 (the mesh follows the nodes), a setup that
    // rebuilds its grid (stretch) or vtkGridEvery: mesh_<lstp>.vtk with each mpData file
    const std::string root = std::string(AMPLE_TEST_TMP) + "/output_grids";
    auto run = [&](const char* setup, const std::string& dir, bool every, bool fem) {
      const Setup* s = findSetup(setup);
      Params P = s->params();
      setParam(P, "lstps", 2);
      if (std::string(setup) == "compaction") setParam(P, "nelsy", 4), setParam(P, "E", 1e6);
      if (fem) setParam(P, "fem", 1);
      RunOptions opt{dir, 1, true};
      opt.vtkGridEvery = every;
      REQUIRE(ample::ample(*s, P, opt) == 0);
    };
    auto has = [](const std::string& f) { return std::filesystem::exists(f); };
    run("compaction", root + "/default", false, false);
    CHECK(has(root + "/default/mesh.vtk"));
    CHECK(has(root + "/default/mpData_2.vtk"));
    CHECK(!has(root + "/default/mesh_1.vtk"));
    CHECK(!has(root + "/default/mesh_2.vtk"));
    run("compaction", root + "/every", true, false);
    CHECK(has(root + "/every/mesh.vtk"));
    CHECK(has(root + "/every/mesh_1.vtk"));
    CHECK(has(root + "/every/mesh_2.vtk"));
    run("stretch", root + "/stretch", false, false);
    CHECK(has(root + "/stretch/mesh_2.vtk"));
    run("doughnut", root + "/fem", false, true);
    CHECK(has(root + "/fem/mesh.vtk"));
    CHECK(has(root + "/fem/mesh_1.vtk"));
    CHECK(has(root + "/fem/mesh_2.vtk"));
  }
}
