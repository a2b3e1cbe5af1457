// Tests of readGmsh: the shipped Gmsh meshes setups/meshes/plate.msh (triangles) and
// plate_quad.msh (quadrilaterals) of setups/meshes/plate.geo, a unit square with a hole
// of radius 0.2. References independent of the reader: the geometry of each named
// boundary, the area 1 - (hole polygon), the closed-form Hencky stress of a uniform
// stretch on the read mesh (patch test, FE mode: every node on x = F X), and the text
// of the errors for files the reader refuses.
#include "ample/errors.h"
#include "ample/meshes/readGmsh.h"
#include "testProblems.h"
#include <doctest/doctest.h>
#include <cmath>
#include <filesystem>
#include <fstream>

using namespace ample;
using namespace ample::testing;

namespace {
const std::string meshDir = std::string(AMPLE_SOURCE_DIR) + "/setups/meshes/";
double cellArea(const Mesh& m, int e) {  // shoelace
  double A2 = 0;
  for (int a = 0; a < m.cellNodes(); ++a) {
    const int i = m.etpl(e, a), j = m.etpl(e, (a + 1) % m.cellNodes());
    A2 += m.coord(i, 0) * m.coord(j, 1) - m.coord(j, 0) * m.coord(i, 1);
  }
  return 0.5 * A2;
}
std::string writeFile(const std::string& name, const std::string& text) {
  std::filesystem::create_directories(AMPLE_TEST_TMP);
  const std::string path = std::string(AMPLE_TEST_TMP) + "/" + name;
  std::ofstream(path) << text;
  return path;
}
}  // namespace

TEST_SUITE("readGmsh") {
  // measured: 152 nodes, 248 triangles / 124 quads, 16 nodes on the hole; area to 2.2e-16
  TEST_CASE("readGmsh: the shipped plate meshes: cell type, named boundaries on their lines, area 1 - hole polygon") {
    for (const auto& [file, type] : {std::pair{std::string("plate.msh"), MeshType::Tri3},
                                     std::pair{std::string("plate_quad.msh"), MeshType::Quad4}}) {
      CAPTURE(file);
      const GmshMesh g = readGmsh(meshDir + file);
      const Mesh& m = g.mesh;
      CHECK(m.type == type);
      CHECK(m.nels() > 50);
      for (const char* name : {"bottom", "right", "top", "left", "hole", "plate"}) CHECK(g.groups.count(name) == 1);
      CHECK(int(g.groups.at("plate").size()) == m.nodes());  // the surface's group: every node
      double off = 0;
      for (int n : g.groups.at("left")) off = std::max(off, std::abs(m.coord(n, 0)));
      for (int n : g.groups.at("right")) off = std::max(off, std::abs(m.coord(n, 0) - 1));
      for (int n : g.groups.at("bottom")) off = std::max(off, std::abs(m.coord(n, 1)));
      for (int n : g.groups.at("top")) off = std::max(off, std::abs(m.coord(n, 1) - 1));
      for (int n : g.groups.at("hole"))
        off = std::max(off, std::abs(std::hypot(m.coord(n, 0) - 0.5, m.coord(n, 1) - 0.5) - 0.2));
      CHECK(off <= 1e-12);
      double A = 0, Amin = 1;
      for (int e = 0; e < m.nels(); ++e) A += cellArea(m, e), Amin = std::min(Amin, cellArea(m, e));
      const int N = int(g.groups.at("hole").size());  // uniform points round the hole
      const double hole = 0.5 * N * 0.04 * std::sin(2 * M_PI / N);
      MESSAGE(file, ": ", m.nodes(), " nodes, ", m.nels(), " cells, ", N, " on the hole; area - (1 - polygon) ", A - (1 - hole));
      CHECK(Amin > 0);  // every cell anticlockwise
      CHECK(std::abs(A - (1 - hole)) <= 1e-12);
    }
  }
  // measured: stress 1.2e-14 (tri) / 1.7e-14 (quad), nodes 2.2e-16 m
  TEST_CASE("readGmsh: patch test on the read meshes: a uniform stretch on the named boundaries gives the Hencky stress everywhere") {
    for (const std::string file : {"plate.msh", "plate_quad.msh"}) {
      CAPTURE(file);
      const GmshMesh g = readGmsh(meshDir + file);
      const double ex = 0.02, ey = -0.01, E = 1e6, nu = 0.3;
      Analysis an;
      an.mesh = g.mesh;
      an.fem = true;
      an.lstps = 2;
      const Eigen::MatrixX2d X0 = an.mesh.coord;
      for (const char* name : {"bottom", "right", "top", "left", "hole"})
        for (int n : g.groups.at(name))
          an.mesh.bc.insert(an.mesh.bc.end(), {{dof(n, 0), ex * X0(n, 0)}, {dof(n, 1), ey * X0(n, 1)}});
      Common p;
      p.mpType = MpType::MPM;
      p.E = E;
      p.nu = nu;
      fillCells(an.mpData, an.mesh, p, 0.0);
      RunLog log;
      solveRun(an, log);
      REQUIRE(log.lastConverged == 2);
      const double lx = 1 + 2 * ex, ly = 1 + 2 * ey;
      const double dSig = stretchStressError(an.mpData, henckyStretchStress(lx, ly, E, nu));
      double dX = 0;
      for (int n = 0; n < an.mesh.nodes(); ++n)
        dX = std::max(dX, std::abs(an.mesh.coord(n, 0) - lx * X0(n, 0)) + std::abs(an.mesh.coord(n, 1) - ly * X0(n, 1)));
      MESSAGE(file, ": stress ", dSig, ", nodes ", dX, " m");
      CHECK(dSig <= 1e-10);
      CHECK(dX <= 1e-12);
    }
  }
  TEST_CASE("readGmsh: files it refuses name the file and the reason") {
    CHECK_THROWS_WITH_AS(readGmsh(meshDir + "none.msh"), doctest::Contains("none.msh': cannot be opened"), InputError);
    const std::string v2 = writeFile("v2.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n");
    CHECK_THROWS_WITH_AS(readGmsh(v2), doctest::Contains("only version 4.1 ASCII"), InputError);
    const std::string head = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 6 1 6\n2 1 0 6\n1\n2\n3\n4\n5\n6\n"
                             "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0.5 0 0\n0.5 0.5 0\n$EndNodes\n";
    const std::string quad9 = writeFile("t6.msh", head + "$Elements\n1 1 1 1\n2 1 9 1\n1 1 2 3 5 6 4\n$EndElements\n");
    CHECK_THROWS_WITH_AS(readGmsh(quad9), doctest::Contains("element type 9"), InputError);
    const std::string mixed = writeFile("mixed.msh", head + "$Elements\n2 2 1 2\n2 1 2 1\n1 1 2 3\n2 2 3 1\n"
                                                            "2 2 4 4 3 6\n$EndElements\n");
    CHECK_THROWS_WITH_AS(readGmsh(mixed), doctest::Contains("both triangles and quadrilaterals"), InputError);
    const std::string cw = writeFile("cw.msh", head + "$Elements\n1 1 1 1\n2 1 2 1\n1 1 3 2\n$EndElements\n");
    const GmshMesh g = readGmsh(cw);  // written clockwise: turned round
    CHECK(g.mesh.nels() == 1);
    CHECK(cellArea(g.mesh, 0) == doctest::Approx(0.5));
    const std::string lines = writeFile("lines.msh", head + "$Elements\n1 1 1 1\n1 1 1 1\n1 1 2\n$EndElements\n");
    CHECK_THROWS_WITH_AS(readGmsh(lines), doctest::Contains("no triangles or quadrilaterals"), InputError);
  }
}
