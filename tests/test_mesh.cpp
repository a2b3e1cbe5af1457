// Tests of the general background meshes (docs/meshes.md): generalMesh's checks,
// the point search (cellSearch), the triangle and quadrilateral bases (cellBasis),
// standard MPM and CPDI through solve() on a regular grid given as a general
// quadrilateral mesh against the regular grid's own path, the triangle patch
// test, and the refusals (GIMP, ghost penalty, implicit boundaries).
// References are independent of the code tested: containment by sub-triangle
// areas, the bilinear map written out, central differences, the regular grid's
// fast path (SvpMPM, elemForMP) and the analytic Hencky stress of a uniform stretch.
#include "ample/basis/MPMbasis.h"
#include "ample/meshes/elemMPinfoMesh.h"
#include "ample/meshes/cellBasis.h"
#include "ample/meshes/cellSearch.h"
#include "ample/boundaries/cutCells.h"
#include "ample/basis/elemForMP.h"
#include "ample/errors.h"
#include "ample/meshes/generalMesh.h"
#include "ample/remedies/ghostPenalty.h"
#include "ample/basis/nodesForMP.h"
#include "testProblems.h"
#include <doctest/doctest.h>
#include <cmath>
#include <random>

using namespace ample;
using namespace ample::testing;

namespace {
// the regular grid's nodes and cells as a general quadrilateral mesh
Mesh asQuads(const Mesh& grid) {
  Mesh m = generalMesh(grid.coord, grid.etpl);
  m.bc = grid.bc;
  return m;
}
// each square of a regular grid split into two triangles along its ll-ur diagonal
Mesh asTriangles(const Mesh& grid) {
  Eigen::MatrixXi t(2 * grid.nels(), 3);
  for (int e = 0; e < grid.nels(); ++e) {
    t.row(2 * e) << grid.etpl(e, 0), grid.etpl(e, 1), grid.etpl(e, 2);
    t.row(2 * e + 1) << grid.etpl(e, 0), grid.etpl(e, 2), grid.etpl(e, 3);
  }
  Mesh m = generalMesh(grid.coord, t);
  m.bc = grid.bc;
  return m;
}
// a 3 x 3 mesh of the unit square with the interior nodes moved: distorted convex quads
Mesh distortedQuads() {
  Mesh g = formCoord2D(3, 3, 1.0, 1.0);
  Eigen::MatrixX2d x = g.coord;
  x.row(5) += Eigen::RowVector2d(0.08, 0.05);
  x.row(6) += Eigen::RowVector2d(-0.06, 0.09);
  x.row(9) += Eigen::RowVector2d(0.07, -0.08);
  x.row(10) += Eigen::RowVector2d(-0.05, -0.04);
  x.row(1) += Eigen::RowVector2d(0.1, -0.15);  // the outer boundary is no longer a rectangle
  return generalMesh(x, g.etpl);
}
double cross(const Vector2d& a, const Vector2d& b) { return a(0) * b(1) - a(1) * b(0); }
// reference containment: the fan of triangles (x, x_a, x_a+1) covers the cell exactly
// once (sum of |areas| = the cell's area) when x is inside or on it
bool containsByArea(const Mesh& m, int e, const Vector2d& x) {
  const int n = m.cellNodes();
  double A = 0, S = 0;
  for (int a = 0; a < n; ++a) {
    const Vector2d p = m.coord.row(m.etpl(e, a)).transpose(), q = m.coord.row(m.etpl(e, (a + 1) % n)).transpose();
    const Vector2d o = m.coord.row(m.etpl(e, 0)).transpose();
    A += 0.5 * cross(p - o, q - o);
    S += 0.5 * std::abs(cross(p - x, q - x));
  }
  return S <= A * (1 + 1e-12);
}
int lowestContaining(const Mesh& m, const Vector2d& x) {
  for (int e = 0; e < m.nels(); ++e)
    if (containsByArea(m, e, x)) return e;
  return -1;
}
// the bilinear map of quadrilateral e, written out
Vector2d mapQuad(const Mesh& m, int e, const Vector2d& xi) {
  const double xa[4] = {-1, 1, 1, -1}, ea[4] = {-1, -1, 1, 1};
  Vector2d x = Vector2d::Zero();
  for (int a = 0; a < 4; ++a)
    x += 0.25 * (1 + xa[a] * xi(0)) * (1 + ea[a] * xi(1)) * m.coord.row(m.etpl(e, a)).transpose();
  return x;
}
// largest |difference| of stress (relative to the largest stress) and of position
// (relative to the size L) between two runs of the same points
void compareRuns(const Analysis& a, const Analysis& b, double L, double& dSig, double& dX) {
  REQUIRE(a.mpData.size() == b.mpData.size());
  double sMax = 0;
  dSig = dX = 0;
  for (size_t p = 0; p < a.mpData.size(); ++p) {
    sMax = std::max(sMax, a.mpData[p].sig.cwiseAbs().maxCoeff());
    dSig = std::max(dSig, (a.mpData[p].sig - b.mpData[p].sig).cwiseAbs().maxCoeff());
    dX = std::max(dX, (a.mpData[p].mpC - b.mpData[p].mpC).cwiseAbs().maxCoeff() / L);
  }
  dSig /= sMax;
}
// a setup run on its regular grid and again with its grid given as a general quad mesh
void runBothWays(const std::string& name, const std::vector<std::pair<std::string, double>>& set,
                 double L, double& dSig, double& dX) {
  const Setup* s = findSetup(name);
  REQUIRE(s != nullptr);
  Params P = s->params();
  for (const auto& kv : set) setParam(P, kv.first, kv.second);
  Analysis grid = s->setupGrid(P), quads = s->setupGrid(P);
  quads.mesh = asQuads(quads.mesh);
  RunLog l1, l2;
  solveRun(grid, l1);
  solveRun(quads, l2);
  CHECK(l1.totalNRit == l2.totalNRit);
  compareRuns(grid, quads, L, dSig, dX);
}
}  // namespace

TEST_SUITE("generalMesh") {
  TEST_CASE("generalMesh: type, cells and bucket grid of a quad and a triangle mesh") {
    const Mesh q = asQuads(formCoord2D(3, 2, 3.0, 2.0));
    CHECK(q.type == MeshType::Quad4);
    CHECK(!q.regular());
    CHECK(q.cellNodes() == 4);
    CHECK(q.nels() == 6);
    CHECK(q.search.nbx * q.search.nby >= 6);
    const Mesh t = asTriangles(formCoord2D(3, 2, 3.0, 2.0));
    CHECK(t.type == MeshType::Tri3);
    CHECK(t.cellNodes() == 3);
    CHECK(t.nels() == 12);
  }
  TEST_CASE("generalMesh: clockwise, non-convex, degenerate cells and bad node numbers are InputErrors") {
    Eigen::MatrixX2d x(5, 2);
    x << 0, 0, 1, 0, 1, 1, 0, 1, 0.8, 0.8;
    Eigen::MatrixXi cw(1, 4), nc(1, 4), t0(1, 3), bad(1, 3), five(1, 5);
    cw << 0, 3, 2, 1;
    nc << 0, 1, 4, 3;     // (0.8, 0.8) makes a dent: not convex
    t0 << 0, 2, 2;
    bad << 0, 1, 7;
    five << 0, 1, 2, 3, 4;
    CHECK_THROWS_WITH_AS(generalMesh(x, cw), doctest::Contains("clockwise"), InputError);
    Eigen::MatrixX2d xd = x;
    xd.row(4) << 0.3, 0.3;  // inside the triangle 0-1-3: corner 2 of 0-1-4-3 turns right
    CHECK_THROWS_WITH_AS(generalMesh(xd, nc), doctest::Contains("not convex"), InputError);
    CHECK_THROWS_WITH_AS(generalMesh(x, t0), doctest::Contains("degenerate"), InputError);
    CHECK_THROWS_WITH_AS(generalMesh(x, bad), doctest::Contains("names node 7"), InputError);
    CHECK_THROWS_WITH_AS(generalMesh(x, five), doctest::Contains("allowed 3"), InputError);
  }
}

TEST_SUITE("cellSearch") {
  TEST_CASE("cellSearch: quads from a regular grid: interior points, edges to the left / below, vertices, outside") {
    const Mesh g = formCoord2D(3, 2, 3.0, 2.0), q = asQuads(g);
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> rx(0.0, 3.0), ry(0.0, 2.0);
    for (int k = 0; k < 500; ++k) {
      const Vector2d x(rx(gen), ry(gen));
      CAPTURE(x.transpose());
      CHECK(findCell(q, x) == int(std::floor(x(1))) * 3 + int(std::floor(x(0))));
    }
    CHECK(findCell(q, Vector2d(1.0, 0.5)) == 0);  // vertical edge: the cell to the left
    CHECK(findCell(q, Vector2d(2.5, 1.0)) == 2);  // horizontal edge: the cell below
    CHECK(findCell(q, Vector2d(2.0, 1.0)) == 1);  // interior vertex of cells 1, 2, 4, 5
    CHECK(findCell(q, Vector2d(0.0, 0.0)) == 0);
    CHECK(findCell(q, Vector2d(3.0, 2.0)) == 5);  // the far corner
    CHECK(findCell(q, Vector2d(1.0 + 1e-10, 0.5)) == 0);   // within 1e-9 of the edge
    CHECK(findCell(q, Vector2d(1.0 + 1e-8, 0.5)) == 1);
    CHECK(findCell(q, Vector2d(3.0 + 1e-6, 1.0)) == -1);   // outside
    CHECK(findCell(q, Vector2d(-1.0, 5.0)) == -1);
    CHECK_THROWS_WITH_AS(cellOf(q, Vector2d(3.5, 1.0)), doctest::Contains("has left the background quadrilateral mesh"),
                         RunError);
    // the regular grid's own rule agrees wherever both have a cell
    std::array<int, MAXE> e;
    for (const Vector2d& x : {Vector2d(1.0, 0.5), Vector2d(2.5, 1.0), Vector2d(2.0, 1.0), Vector2d(0.3, 1.7)}) {
      elemForMP(g, x, Vector2d::Zero(), e);
      CHECK(findCell(q, x) == e[0]);
    }
  }
  TEST_CASE("cellSearch: distorted quads and triangles: the lowest-numbered cell that holds the point, or -1") {
    for (const Mesh& m : {distortedQuads(), asTriangles(formCoord2D(4, 3, 2.0, 1.5))}) {
      CAPTURE(std::string(meshName(m)));
      const Vector2d lo = m.coord.colwise().minCoeff().transpose(), hi = m.coord.colwise().maxCoeff().transpose();
      std::mt19937 gen(11);
      std::uniform_real_distribution<double> r(-0.05, 1.05);
      int outside = 0;
      for (int k = 0; k < 2000; ++k) {
        const Vector2d x = lo + (hi - lo).cwiseProduct(Vector2d(r(gen), r(gen)));
        CAPTURE(x.transpose());
        const int ref = lowestContaining(m, x);
        CHECK(findCell(m, x) == ref);
        outside += ref < 0;
      }
      CHECK(outside > 50);  // the test did try points outside
      for (int n = 0; n < m.nodes(); ++n) {    // every vertex and every edge midpoint
        const Vector2d x = m.coord.row(n).transpose();
        CHECK(findCell(m, x) == lowestContaining(m, x));
      }
      for (int e = 0; e < m.nels(); ++e)
        for (int a = 0; a < m.cellNodes(); ++a) {
          const Vector2d x = 0.5 * (m.coord.row(m.etpl(e, a)) + m.coord.row(m.etpl(e, (a + 1) % m.cellNodes()))).transpose();
          CHECK(findCell(m, x) == lowestContaining(m, x));
        }
    }
  }
}

TEST_SUITE("cellSearch") {
  // the reference: the exit of the segment point -> corner through the mesh edge found
  // by hand (the square's edge x = 1 or y = 0), and linear reproduction, sum N x = x,
  // of the continued basis; measured 0 / <= 3e-16
  TEST_CASE("cornerCell: a corner outside the mesh takes the cell where the line from its point leaves the mesh; the continued basis reproduces x") {
    for (const Mesh& m : {distortedQuads(), asTriangles(formCoord2D(4, 3, 2.0, 1.5))}) {
      CAPTURE(std::string(meshName(m)));
      const double xmax = m.coord.col(0).maxCoeff();
      struct Case { Vector2d p, c, exit; };
      const Case cases[] = {{Vector2d(xmax - 0.2, 0.7), Vector2d(xmax + 0.3, 0.9), Vector2d(xmax, 0.78)},
                            {Vector2d(0.35, 0.1), Vector2d(0.45, -0.3), Vector2d(0.375, 0.0)}};
      for (const Case& k : cases) {
        REQUIRE(findCell(m, k.p) >= 0);
        REQUIRE(findCell(m, k.c) < 0);
        const int e = cornerCell(m, k.c, k.p);
        CHECK(e == findCell(m, k.exit - 1e-7 * (k.c - k.p)));  // the cell just inside the exit
        const CellBasis b = cellBasis(m, e, k.c);
        Vector2d X = Vector2d::Zero();
        double S = 0;
        for (int a = 0; a < m.cellNodes(); ++a) S += b.N[a], X += b.N[a] * m.coord.row(m.etpl(e, a)).transpose();
        CHECK(std::abs(S - 1) <= 1e-14);
        CHECK((X - k.c).norm() <= 1e-13);
      }
      const Vector2d in(0.3, 0.4), onEdge(0.3, 0.0);  // inside / on the mesh edge: the cell holding it
      CHECK(cornerCell(m, in, Vector2d(0.35, 0.45)) == findCell(m, in));
      CHECK(cornerCell(m, onEdge, Vector2d(0.35, 0.45)) == findCell(m, onEdge));
      CHECK_THROWS_AS(cornerCell(m, Vector2d(-1, -1), Vector2d(-0.5, -0.5)), RunError);  // point outside too
    }
  }
}

TEST_SUITE("cellBasis") {
  // measured: partition of unity and sum of gradients to < 3e-16 / 2e-15; linear
  // reproduction < 3e-16; central differences (step 1e-6) < 2e-10 on the triangles
  // and the distorted quads; Newton 3-5 passes on the distorted quads
  TEST_CASE("cellBasis: partition of unity / linear reproduction / central-difference gradients") {
    for (const Mesh& m : {distortedQuads(), asTriangles(formCoord2D(2, 2, 1.0, 1.0)),
                          asQuads(formCoord2D(2, 2, 1.0, 1.0))}) {
      CAPTURE(std::string(meshName(m)));
      std::mt19937 gen(5);
      std::uniform_real_distribution<double> r(0.0, 1.0);
      double pu = 0, sg = 0, lin = 0, fd = 0;
      int passes = 0;
      for (int k = 0; k < 300; ++k) {
        const int e = k % m.nels();
        Vector2d x;  // a random point of cell e
        do {
          x = Vector2d(r(gen), r(gen));
        } while (!containsByArea(m, e, x));
        const CellBasis b = cellBasis(m, e, x);
        passes = std::max(passes, b.passes);
        double S = 0;
        Vector2d G = Vector2d::Zero(), X = Vector2d::Zero();
        for (int a = 0; a < m.cellNodes(); ++a) {
          S += b.N[a], G += b.dN.col(a);
          X += b.N[a] * m.coord.row(m.etpl(e, a)).transpose();
        }
        pu = std::max(pu, std::abs(S - 1)), sg = std::max(sg, G.cwiseAbs().maxCoeff());
        lin = std::max(lin, (X - x).cwiseAbs().maxCoeff());
        const double d = 1e-6;
        for (int i = 0; i < 2; ++i) {
          Vector2d xp = x, xm = x;
          xp(i) += d, xm(i) -= d;
          const CellBasis bp = cellBasis(m, e, xp), bm = cellBasis(m, e, xm);
          for (int a = 0; a < m.cellNodes(); ++a)
            fd = std::max(fd, std::abs((bp.N[a] - bm.N[a]) / (2 * d) - b.dN(i, a)));
        }
      }
      MESSAGE(std::string(meshName(m)), ": |sum N - 1| ", pu, ", |sum dN| ", sg, ", |sum N x - x| ", lin,
              ", FD ", fd, ", Newton passes <= ", passes);
      CHECK(pu <= 1e-14);
      CHECK(sg <= 1e-13);
      CHECK(lin <= 1e-14);
      CHECK(fd <= 1e-8);
      CHECK(passes <= 8);
    }
  }
  TEST_CASE("cellBasis: distorted quad: Newton inverts the bilinear map to 1e-14 and N_a(x_b) = delta_ab") {
    const Mesh m = distortedQuads();
    for (int e = 0; e < m.nels(); ++e)
      for (const Vector2d& xi : {Vector2d(0.3, -0.7), Vector2d(-0.99, 0.95), Vector2d(1.0, 1.0), Vector2d(0, 0)}) {
        const CellBasis b = cellBasis(m, e, mapQuad(m, e, xi));
        CHECK((b.xi - xi).cwiseAbs().maxCoeff() <= 1e-14);
      }
    for (int a = 0; a < 4; ++a) {
      const CellBasis b = cellBasis(m, 4, m.coord.row(m.etpl(4, a)).transpose());
      for (int c = 0; c < 4; ++c) CHECK(std::abs(b.N[c] - (a == c)) <= 1e-14);
    }
  }
  TEST_CASE("cellBasis: regular quads as a general mesh give the grid's tensor-product basis (SvpMPM) to 1e-15") {
    const Mesh g = formCoord2D(3, 2, 1.5, 1.0), q = asQuads(g);
    MaterialPoint pg, pq;
    pg.mpType = pq.mpType = MpType::MPM;
    pg.nn = MAXN;                   // room for any nodesForMP
    pq.nn = MAXN;
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> r(0.0, 1.0);
    double dS = 0, dG = 0;
    for (int k = 0; k < 200; ++k) {
      pg.mpC = pq.mpC = Vector2d(1.5 * r(gen), r(gen));
      pg.ne = elemForMP(g, pg.mpC, pg.lp, pg.eIN);
      pq.ne = meshElemForMP(q, pq.mpC, pq.lp, pq.eIN);
      REQUIRE(pq.ne == 1);
      CHECK(pq.eIN[0] == pg.eIN[0]);
      pg.nn = nodesForMP(g, pg.eIN, pg.ne, pg.nIN.data());
      pq.nn = nodesForMP(q, pq.eIN, pq.ne, pq.nIN.data());
      MPMbasis(g, pg);
      meshMPMbasis(q, pq);
      for (int v = 0; v < 4; ++v) {
        dS = std::max(dS, std::abs(pg.Svp[v] - pq.Svp[v]));
        dG = std::max(dG, (pg.dSvp.col(v) - pq.dSvp.col(v)).cwiseAbs().maxCoeff());
      }
    }
    MESSAGE("grid vs general quads: |dS| ", dS, ", |d grad S| ", dG);
    CHECK(dS <= 1e-15);
    CHECK(dG <= 1e-13);
  }
  TEST_CASE("cellBasis: scalene triangles of different areas: N and grad N against the barycentric system solved by hand") {
    // three anticlockwise triangles (2A = 3.43, 3.56, 2.78), none right-angled or axis-aligned
    Eigen::MatrixX2d coord(5, 2);
    coord << 0.2, -0.1, 2.3, 0.4, 0.9, 1.7, 3.1, 2.2, -0.8, 1.3;
    Eigen::MatrixXi tri(3, 3);
    tri << 0, 1, 2, 1, 3, 2, 0, 2, 4;
    const Mesh m = generalMesh(coord, tri);
    const double twoA[3] = {3.43, 3.56, 2.78};
    const double r[5][2] = {{0.2, 0.3}, {0.61, 0.17}, {0.05, 0.9}, {0.33, 0.33}, {0.7, 0.02}};
    for (int rep = 0; rep < 2; ++rep)
      for (int e = 0; e < 3; ++e) {
        CAPTURE(e);
        // [1 1 1; x0 x1 x2; y0 y1 y2] N = [1; x; y]: N = M^-1 [1; x; y], grad N_a = row a of M^-1, cols 1-2
        Eigen::Matrix3d M;
        for (int a = 0; a < 3; ++a)
          M.col(a) << 1.0, m.coord(m.etpl(e, a), 0), m.coord(m.etpl(e, a), 1);
        CHECK(std::abs(M.determinant() - twoA[e]) <= 1e-12);
        const Eigen::Matrix3d Minv = M.inverse();
        for (const auto& rr : r) {  // x = X0 + r0 (X1 - X0) + r1 (X2 - X0): N1 = r0, N2 = r1
          const Vector2d X0 = m.coord.row(m.etpl(e, 0)).transpose();
          const Vector2d x = X0 + rr[0] * (m.coord.row(m.etpl(e, 1)).transpose() - X0) +
                             rr[1] * (m.coord.row(m.etpl(e, 2)).transpose() - X0);
          CAPTURE(x.transpose());
          const CellBasis b = cellBasis(m, e, x);
          const Eigen::Vector3d N = Minv * Eigen::Vector3d(1.0, x(0), x(1));
          CHECK(std::abs(N(1) - rr[0]) <= 1e-14);
          CHECK(std::abs(N(2) - rr[1]) <= 1e-14);
          double S = 0;
          Vector2d X = Vector2d::Zero(), G = Vector2d::Zero();
          for (int a = 0; a < 3; ++a) {
            CAPTURE(a);
            CHECK(std::abs(b.N[a] - N(a)) <= 1e-14);
            CHECK(std::abs(b.dN(0, a) - Minv(a, 1)) <= 1e-13);
            CHECK(std::abs(b.dN(1, a) - Minv(a, 2)) <= 1e-13);
            S += b.N[a], G += b.dN.col(a), X += b.N[a] * m.coord.row(m.etpl(e, a)).transpose();
            const double d = 1e-6;
            for (int i = 0; i < 2; ++i) {
              Vector2d xp = x, xm = x;
              xp(i) += d, xm(i) -= d;
              CHECK(std::abs((cellBasis(m, e, xp).N[a] - cellBasis(m, e, xm).N[a]) / (2 * d) - b.dN(i, a)) <= 1e-8);
            }
          }
          CHECK(std::abs(S - 1.0) <= 1e-14);
          CHECK(G.norm() <= 1e-13);
          CHECK((X - x).norm() <= 1e-14);
          CHECK((b.xi - Vector2d(rr[0], rr[1])).norm() <= 1e-14);
        }
      }
  }
  TEST_CASE("cellBasis: a point on a triangle's edge gives the node off that edge exactly N = 0") {
    // 200 points along each edge of the scalene triangles: the round-off of the position must
    // not leave N = 1e-17 (or -1e-17) for the opposite node (dropNullNodes, detFDoFs test N == 0)
    Eigen::MatrixX2d coord(5, 2);
    coord << 0.2, -0.1, 2.3, 0.4, 0.9, 1.7, 3.1, 2.2, -0.8, 1.3;
    Eigen::MatrixXi tri(3, 3);
    tri << 0, 1, 2, 1, 3, 2, 0, 2, 4;
    const Mesh m = generalMesh(coord, tri);
    int nonZero = 0;
    for (int e = 0; e < 3; ++e)
      for (int a = 0; a < 3; ++a) {  // the edge from node a + 1 to node a + 2, opposite node a
        const Vector2d P = m.coord.row(m.etpl(e, (a + 1) % 3)).transpose();
        const Vector2d Q = m.coord.row(m.etpl(e, (a + 2) % 3)).transpose();
        for (int k = 1; k < 200; ++k) {
          const double s = k / 200.0 + 1e-3 / 7;
          const CellBasis b = cellBasis(m, e, P + s * (Q - P));
          if (b.N[a] != 0.0) ++nonZero;
          CHECK(std::abs(b.N[a]) <= 1e-14);
        }
      }
    CHECK(nonZero == 0);
  }
}

TEST_SUITE("meshRuns") {
  // measured (relative stress difference, position difference / size): see the MESSAGEs
  TEST_CASE("meshRuns: standard MPM on the grid as a general quad mesh equals the regular grid to 1e-12 (compaction, collapse)") {
    double dSig, dX;
    runBothWays("compaction", {{"mpType", 1}, {"nelsy", 8}, {"lstps", 10}}, 50.0, dSig, dX);
    MESSAGE("compaction MPM: stress ", dSig, ", position ", dX);
    CHECK(dSig <= 1e-12);
    CHECK(dX <= 1e-12);
    runBothWays("collapse", {{"mpType", 1}, {"a", 1}, {"lstps", 10}}, 8.0, dSig, dX);
    MESSAGE("collapse MPM (von Mises): stress ", dSig, ", position ", dX);
    CHECK(dSig <= 1e-12);
    CHECK(dX <= 1e-12);
  }
  TEST_CASE("meshRuns: CPDI2 and CPDI1 on the grid as a general quad mesh equal the regular grid to 1e-12 (collapse, compaction; shear 1e-5)") {
    double dSig, dX;
    runBothWays("collapse", {{"mpType", 4}, {"a", 1}, {"lstps", 10}}, 8.0, dSig, dX);
    MESSAGE("collapse CPDI2: stress ", dSig, ", position ", dX);
    CHECK(dSig <= 1e-12);
    CHECK(dX <= 1e-12);
    // the shear differs more (measured 6.7e-7 / 7.9e-9): its corners sit on grid lines, where
    // the regular path's SvpMPM gives round-off values (3.7e-18) to nodes off the line and so
    // links them; the general path puts the corner on the edge (N = 0 exactly) and drops them
    runBothWays("shear", {{"mpType", 4}}, 1.0, dSig, dX);
    MESSAGE("shear CPDI2: stress ", dSig, ", position ", dX);
    CHECK(dSig <= 1e-5);
    CHECK(dX <= 1e-7);
    runBothWays("compaction", {{"mpType", 4}, {"nelsy", 8}, {"lstps", 10}}, 50.0, dSig, dX);
    MESSAGE("compaction CPDI2: stress ", dSig, ", position ", dX);
    CHECK(dSig <= 1e-12);
    CHECK(dX <= 1e-12);
    runBothWays("compaction", {{"mpType", 3}, {"nelsy", 8}, {"lstps", 10}}, 50.0, dSig, dX);
    MESSAGE("compaction CPDI1: stress ", dSig, ", position ", dX);
    CHECK(dSig <= 1e-12);
    CHECK(dX <= 1e-12);
  }
  TEST_CASE("meshRuns: triangles from split squares reproduce a uniform stretch (patch test): Hencky stress to 1e-10") {
    const double L = 2.0, ex = 0.01, ey = -0.005, E = 1e6, nu = 0.3;
    Mesh g = formCoord2D(4, 4, L, L);
    for (int n = 0; n < g.nodes(); ++n) {  // the linear field on the boundary nodes only
      const double X = g.coord(n, 0), Y = g.coord(n, 1);
      if (X < 1e-9 || X > L - 1e-9 || Y < 1e-9 || Y > L - 1e-9)
        g.bc.insert(g.bc.end(), {{dof(n, 0), ex * X}, {dof(n, 1), ey * Y}});
    }
    Analysis an;
    an.mesh = asTriangles(g);
    for (int e = 0; e < an.mesh.nels(); ++e) {  // three points per triangle, V = A / 3
      Eigen::Matrix<double, 2, 3> X;
      for (int a = 0; a < 3; ++a) X.col(a) = an.mesh.coord.row(an.mesh.etpl(e, a)).transpose();
      const double A = 0.5 * cross(X.col(1) - X.col(0), X.col(2) - X.col(0));
      for (int a = 0; a < 3; ++a) {
        MaterialPoint mp;
        mp.mpType = MpType::MPM;
        mp.mpC = mp.X0 = (2.0 / 3) * X.col(a) + (1.0 / 6) * (X.col((a + 1) % 3) + X.col((a + 2) % 3));
        mp.vp = mp.vp0 = A / 3;
        mp.mCst = {E, nu, 0};
        an.mpData.push_back(mp);
      }
    }
    RunLog log;
    solveRun(an, log);
    const double dSig = stretchStressError(an.mpData, henckyStretchStress(1 + ex, 1 + ey, E, nu));
    double dU = 0;
    for (int n = 0; n < an.mesh.nodes(); ++n)
      dU = std::max(dU, std::abs(an.uvw(dof(n, 0)) - ex * an.mesh.coord(n, 0)) +
                            std::abs(an.uvw(dof(n, 1)) - ey * an.mesh.coord(n, 1)));
    MESSAGE("triangle patch test: stress ", dSig, ", interior nodal displacement ", dU, " m");
    CHECK(dSig <= 1e-10);
    CHECK(dU <= 1e-12);
  }
}

namespace {
Params gimpParams(Common& p) {  // GIMP: Common's default
  return commonParams(p);
}
Analysis gimpOnQuads(const Common& p) {
  Analysis an;
  an.mesh = asQuads(formCoord2D(4, 4, 4.0, 4.0));
  fillBlock(an.mpData, Vector2d(1, 1), 2, 2, Vector2d(1, 1), p, 1000.0);
  return an;
}
Results noResults(const Analysis&, const Common&) { return {}; }
}  // namespace

TEST_SUITE("meshRefusals") {
  TEST_CASE("meshRefusals: GIMP on a general mesh is an InputError naming mpType and the mesh (ample() and solve())") {
    const Setup s{"gimpquads", "GIMP on a general mesh (test)", {gimpParams, gimpOnQuads, noResults}};
    RunOptions opt{AMPLE_TEST_TMP "/gimpquads", 0, true, 0};
    CHECK_THROWS_WITH_AS(ample::ample(s, s.params(), opt),
                         doctest::Contains("mpType=2 (GIMP) needs the regular grid; the background mesh is a "
                                           "quadrilateral mesh"), InputError);
    Analysis an = gimpOnQuads(Common());
    RunLog log;
    CHECK_THROWS_WITH_AS(solveRun(an, log), doctest::Contains("mpType=2 (GIMP)"), InputError);
    MaterialPoint mp = an.mpData[0];
    mp.nn = MAXN;
    mp.ne = 1, mp.eIN[0] = findCell(an.mesh, mp.mpC), mp.nn = nodesForMP(an.mesh, mp.eIN, 1, mp.nIN.data());
    CHECK_THROWS_AS(meshMPMbasis(an.mesh, mp), InputError);
  }
  TEST_CASE("meshRefusals: ghost penalty and implicit boundaries refuse a general mesh") {
    const Mesh q = asQuads(formCoord2D(2, 2, 1.0, 1.0));
    CHECK_THROWS_WITH_AS(ghostPenalty(q, 1e-3, 1e6), doctest::Contains("regular grid"), InputError);
    Boundary b;
    b.x = {Vector2d(0.1, 0.1), Vector2d(0.9, 0.1)};
    b.type = {BoundaryType::Fixed};
    CHECK_THROWS_WITH_AS(cutCells(q, b), doctest::Contains("regular grid"), InputError);
  }
}
