// Tests of the grid functions: formCoord2D, detMpPos, shapefunc, elemForMP,
// nodesForMP (cells and nodes linked to points near cell edges).
#include "ample/detMpPos.h"
#include "ample/elemForMP.h"
#include "ample/errors.h"
#include "ample/formCoord2D.h"
#include "ample/nodesForMP.h"
#include "ample/shapefunc.h"
#include <doctest/doctest.h>

using namespace ample;

namespace {
int cellsOf(const Mesh& mesh, Vector2d x, Vector2d lp, std::array<int, MAXE>& e) {
  return elemForMP(mesh, x, lp, e);
}
}  // namespace

TEST_SUITE("grid") {
  TEST_CASE("formCoord2D: node coordinates and anticlockwise cells of positive area") {
    const Mesh m = formCoord2D(3, 2, 6.0, 2.0);
    REQUIRE(m.nodes() == 12);
    REQUIRE(m.nels() == 6);
    CHECK(m.h == Vector2d(2.0, 1.0));
    CHECK(m.coord(11, 0) == 6.0);
    CHECK(m.coord(11, 1) == 2.0);
    for (int e = 0; e < m.nels(); ++e) {
      double area = 0;  // shoelace formula
      for (int a = 0; a < nen; ++a) {
        const int p = m.etpl(e, a), q = m.etpl(e, (a + 1) % nen);
        area += 0.5 * (m.coord(p, 0) * m.coord(q, 1) - m.coord(q, 0) * m.coord(p, 1));
      }
      CHECK(area == doctest::Approx(2.0).epsilon(1e-14));
    }
  }
  TEST_CASE("detMpPos: mp x mp points, symmetric, spacing 2/mp inside [-1, 1]") {
    for (int mp = 1; mp <= 6; ++mp) {
      const Eigen::MatrixX2d p = detMpPos(mp);
      REQUIRE(p.rows() == mp * mp);
      CHECK(std::abs(p.col(0).sum()) <= 1e-13);
      CHECK(std::abs(p.col(1).sum()) <= 1e-13);
      CHECK(p.cwiseAbs().maxCoeff() == doctest::Approx(1.0 - 1.0 / mp).epsilon(1e-14));
      if (mp > 1) CHECK(p(1, 1) - p(0, 1) == doctest::Approx(2.0 / mp).epsilon(1e-14));
    }
  }
  TEST_CASE("shapefunc: partition of unity and Kronecker property at the corners") {
    const double c[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int a = 0; a < 4; ++a) {
      const Eigen::Vector4d N = shapefunc(Vector2d(c[a][0], c[a][1]));
      for (int b = 0; b < 4; ++b) CHECK(N(b) == (a == b ? 1.0 : 0.0));
    }
    CHECK(shapefunc(Vector2d(0.3, -0.7)).sum() == doctest::Approx(1.0).epsilon(1e-15));
  }
  TEST_CASE("elemForMP: cells of points and domains near cell edges") {
    const Mesh m = formCoord2D(4, 4, 4.0, 4.0);
    std::array<int, MAXE> e;
    CHECK(cellsOf(m, Vector2d(1.5, 1.5), Vector2d::Zero(), e) == 1);
    CHECK(e[0] == 5);
    REQUIRE(cellsOf(m, Vector2d(2.0, 1.5), Vector2d::Zero(), e) == 1);  // MPM on an edge
    CHECK(e[0] == 6);                                                   // the cell to the right
    CHECK(cellsOf(m, Vector2d(2.05, 1.5), Vector2d(0.1, 0.1), e) == 2);  // straddles x = 2
    CHECK(cellsOf(m, Vector2d(1.95, 2.05), Vector2d(0.1, 0.1), e) == 4); // a corner
    CHECK(cellsOf(m, Vector2d(1.75, 1.5), Vector2d(0.25, 0.25), e) == 1); // touches x = 2 only
    CHECK(e[0] == 5);
    CHECK(cellsOf(m, Vector2d(0.05, 0.05), Vector2d(0.1, 0.1), e) == 1);  // cut at the grid edge
    CHECK_THROWS_AS(cellsOf(m, Vector2d(4.2, 1.0), Vector2d::Zero(), e), RunError);
    CHECK_THROWS_AS(cellsOf(m, Vector2d(1.0, -0.1), Vector2d(0.2, 0.2), e), RunError);
  }
  TEST_CASE("nodesForMP: unique ascending nodes of 1, 2 and 4 cells") {
    const Mesh m = formCoord2D(4, 4, 4.0, 4.0);
    std::array<int, MAXN> n;
    std::array<int, MAXE> e{5, 6, 9, 10};
    CHECK(nodesForMP(m, e, 1, n) == 4);
    CHECK(nodesForMP(m, e, 2, n) == 6);
    REQUIRE(nodesForMP(m, e, 4, n) == 9);
    for (int k = 1; k < 9; ++k) CHECK(n[k] > n[k - 1]);
    CHECK(n[0] == 6);
    CHECK(n[8] == 18);
  }
}
