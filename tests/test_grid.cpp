// Tests of the grid functions: formCoord2D, detMpPos, shapefunc, elemForMP,
// nodesForMP (cells and nodes linked to points near cell edges).
#include "setups/detMpPos.h"
#include "ample/basis/elemForMP.h"
#include "ample/errors.h"
#include "setups/formCoord2D.h"
#include "ample/basis/nodesForMP.h"
#include "setups/shapefunc.h"
#include <doctest/doctest.h>
#include <cmath>
#include <vector>

using namespace ample;

namespace {
// the cells elemForMP links to a point at x with domain half lengths lp
std::vector<int> cellsOf(const Mesh& mesh, Vector2d x, Vector2d lp) {
  std::array<int, MAXE> e;
  const int ne = elemForMP(mesh, x, lp, e);
  return std::vector<int>(e.begin(), e.begin() + ne);
}
std::vector<int> nodesOf(const Mesh& mesh, std::vector<int> cells) {
  std::array<int, MAXE> e;
  std::copy(cells.begin(), cells.end(), e.begin());
  std::array<int, MAXN> n;
  const int nn = nodesForMP(mesh, e, int(cells.size()), n.data());
  return std::vector<int>(n.begin(), n.begin() + nn);
}
}  // namespace

TEST_SUITE("formCoord2D") {
  TEST_CASE("formCoord2D: node count / coordinates row by row / spacing") {
    const Mesh m = formCoord2D(3, 2, 6.0, 2.0);
    REQUIRE(m.nodes() == 12);
    REQUIRE(m.nels() == 6);
    CHECK(m.nelsx == 3);
    CHECK(m.nelsy == 2);
    CHECK(m.h == Vector2d(2.0, 1.0));
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 3; ++i) {  // x fastest
        CAPTURE(i);
        CAPTURE(j);
        CHECK(std::abs(m.coord(4 * j + i, 0) - 2.0 * i) <= 1e-14);
        CHECK(std::abs(m.coord(4 * j + i, 1) - 1.0 * j) <= 1e-14);
      }
  }
  TEST_CASE("formCoord2D: cells anticlockwise from the lower-left node / positive area h_x h_y") {
    const Mesh m = formCoord2D(3, 2, 6.0, 2.0);
    for (int e = 0; e < m.nels(); ++e) {
      CAPTURE(e);
      double area = 0;  // shoelace formula: positive for anticlockwise nodes
      for (int a = 0; a < nen; ++a) {
        const int p = m.etpl(e, a), q = m.etpl(e, (a + 1) % nen);
        area += 0.5 * (m.coord(p, 0) * m.coord(q, 1) - m.coord(q, 0) * m.coord(p, 1));
      }
      CHECK(area == doctest::Approx(2.0).epsilon(1e-14));
      const int ll = m.etpl(e, 0);  // lower-left node of cell (e % 3, e / 3)
      CHECK(m.coord(ll, 0) == doctest::Approx(2.0 * (e % 3)).epsilon(1e-14).scale(1.0));
      CHECK(m.coord(ll, 1) == doctest::Approx(1.0 * (e / 3)).epsilon(1e-14).scale(1.0));
    }
  }
}

TEST_SUITE("detMpPos") {
  TEST_CASE("detMpPos: mp x mp points / symmetric / spacing 2/mp inside [-1 / 1]") {
    for (int mp = 1; mp <= 6; ++mp) {
      CAPTURE(mp);
      const Eigen::MatrixX2d p = detMpPos(mp);
      REQUIRE(p.rows() == mp * mp);
      CHECK(std::abs(p.col(0).sum()) <= 1e-13);  // symmetric about the cell centre
      CHECK(std::abs(p.col(1).sum()) <= 1e-13);
      CHECK(p.cwiseAbs().maxCoeff() == doctest::Approx(1.0 - 1.0 / mp).epsilon(1e-14));
      for (int i = 0; i < mp; ++i)  // (2i+1)/mp - 1, xi outer, eta inner
        for (int j = 0; j < mp; ++j) {
          CHECK(std::abs(p(i * mp + j, 0) - ((2.0 * i + 1) / mp - 1)) <= 1e-15);
          CHECK(std::abs(p(i * mp + j, 1) - ((2.0 * j + 1) / mp - 1)) <= 1e-15);
        }
      if (mp > 1) CHECK(p(1, 1) - p(0, 1) == doctest::Approx(2.0 / mp).epsilon(1e-14));
    }
  }
}

TEST_SUITE("shapefunc") {
  TEST_CASE("shapefunc: partition of unity and Kronecker property at the corners") {
    const double c[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int a = 0; a < 4; ++a) {
      const Eigen::Vector4d N = shapefunc(Vector2d(c[a][0], c[a][1]));
      for (int b = 0; b < 4; ++b) CHECK(N(b) == (a == b ? 1.0 : 0.0));
    }
    for (Vector2d xi : {Vector2d(0.3, -0.7), Vector2d(0, 0), Vector2d(-0.9, 0.45)}) {
      const Eigen::Vector4d N = shapefunc(xi);
      CHECK(N.sum() == doctest::Approx(1.0).epsilon(1e-15));
      Vector2d x = Vector2d::Zero();  // reproduces the local coordinates (linear completeness)
      for (int a = 0; a < 4; ++a) x += N(a) * Vector2d(c[a][0], c[a][1]);
      CHECK((x - xi).norm() <= 1e-15);
    }
    CHECK(shapefunc(Vector2d(0, 0))(2) == doctest::Approx(0.25).epsilon(1e-15));
  }
}

TEST_SUITE("elemForMP") {
  // 4 x 4 cells of 1 m; cell (i, j) is number 4 j + i
  TEST_CASE("elemForMP: a point strictly inside a cell has that cell only") {
    const Mesh m = formCoord2D(4, 4, 4.0, 4.0);
    CHECK(cellsOf(m, Vector2d(1.5, 1.5), Vector2d::Zero()) == std::vector<int>{5});
    CHECK(cellsOf(m, Vector2d(3.9, 0.1), Vector2d::Zero()) == std::vector<int>{3});
    CHECK(cellsOf(m, Vector2d(1.5, 1.5), Vector2d(0.2, 0.3)) == std::vector<int>{5});
  }
  TEST_CASE("elemForMP: an MPM point on a cell edge belongs to the cell to the left / below") {
    // the intervals X_k < x <= X_k+1 of SvpMPM (eq 23), so that the cell's nodes carry
    // the basis gradients the point actually has (a point on x = 2 moved by a shear
    // with the wrong cell's nodes got a wrong dF)
    const Mesh m = formCoord2D(4, 4, 4.0, 4.0);
    CHECK(cellsOf(m, Vector2d(2.0, 1.5), Vector2d::Zero()) == std::vector<int>{5});   // left
    CHECK(cellsOf(m, Vector2d(1.5, 2.0), Vector2d::Zero()) == std::vector<int>{5});   // below
    CHECK(cellsOf(m, Vector2d(2.0, 2.0), Vector2d::Zero()) == std::vector<int>{5});   // corner
    CHECK(cellsOf(m, Vector2d(0.0, 0.5), Vector2d::Zero()) == std::vector<int>{0});   // grid edge
  }
  TEST_CASE("elemForMP: an MPM point within round-off of a cell edge belongs to the cell to the left / below") {
    // a position that should sit on x = 2 carries round-off of either sign (after
    // simple shear x = X + gamma Y lands on grid lines): both sides must give the same
    // cell, or a row of points is split 4 / 2 between two cells ([Lagrangian] sec 7.2)
    const Mesh m = formCoord2D(4, 4, 4.0, 4.0);
    CHECK(cellsOf(m, Vector2d(2.0 + 4e-16, 1.5), Vector2d::Zero()) == std::vector<int>{5});
    CHECK(cellsOf(m, Vector2d(2.0 - 4e-16, 1.5), Vector2d::Zero()) == std::vector<int>{5});
    CHECK(cellsOf(m, Vector2d(1.5, 2.0 + 4e-16), Vector2d::Zero()) == std::vector<int>{5});
    CHECK(cellsOf(m, Vector2d(2.0 + 1e-6, 1.5), Vector2d::Zero()) == std::vector<int>{6});  // really right
  }
  TEST_CASE("elemForMP: a GIMP domain straddling an edge has 2 cells / a corner 4") {
    const Mesh m = formCoord2D(4, 4, 4.0, 4.0);
    CHECK(cellsOf(m, Vector2d(2.05, 1.5), Vector2d(0.1, 0.1)) == std::vector<int>{5, 6});
    CHECK(cellsOf(m, Vector2d(1.5, 1.95), Vector2d(0.1, 0.1)) == std::vector<int>{5, 9});
    CHECK(cellsOf(m, Vector2d(1.95, 2.05), Vector2d(0.1, 0.1)) == std::vector<int>{5, 6, 9, 10});
  }
  TEST_CASE("elemForMP: a cell that only touches the domain edge is not linked") {
    const Mesh m = formCoord2D(4, 4, 4.0, 4.0);
    // domain [1.5, 2] x [1.25, 1.75]: its right edge is the cell edge x = 2
    CHECK(cellsOf(m, Vector2d(1.75, 1.5), Vector2d(0.25, 0.25)) == std::vector<int>{5});
    // domain [2, 2.5] x [1, 1.5]: left edge x = 2 and bottom edge y = 1
    CHECK(cellsOf(m, Vector2d(2.25, 1.25), Vector2d(0.25, 0.25)) == std::vector<int>{6});
    // the domain [1, 2] x [1, 2] fills cell 5 exactly
    CHECK(cellsOf(m, Vector2d(1.5, 1.5), Vector2d(0.5, 0.5)) == std::vector<int>{5});
  }
  TEST_CASE("elemForMP: a domain reaching past the grid edge keeps the cells inside") {
    const Mesh m = formCoord2D(4, 4, 4.0, 4.0);
    CHECK(cellsOf(m, Vector2d(0.05, 0.05), Vector2d(0.1, 0.1)) == std::vector<int>{0});
    CHECK(cellsOf(m, Vector2d(3.95, 3.95), Vector2d(0.1, 0.1)) == std::vector<int>{15});
    CHECK(cellsOf(m, Vector2d(3.95, 1.5), Vector2d(0.1, 0.1)) == std::vector<int>{7});
  }
  TEST_CASE("elemForMP: a domain too long for a point's 16 nodes throws RunError (no overrun)") {
    // 8 x 1 cells are within MAXE = 9 but have 9 x 2 = 18 nodes > MAXN = 16 (a GIMP domain
    // stretched by its domain update wrote past the point's node arrays)
    const Mesh m = formCoord2D(10, 10, 10.0, 10.0);
    std::array<int, MAXE> e;
    CHECK_THROWS_AS(elemForMP(m, Vector2d(5.0, 5.5), Vector2d(3.9, 0.4), e), RunError);
    CHECK_THROWS_AS(elemForMP(m, Vector2d(5.5, 5.0), Vector2d(1.9, 0.45), e), RunError);  // 5 x 2
    CHECK_THROWS_AS(elemForMP(m, Vector2d(5.0, 5.0), Vector2d(NAN, 0.4), e), RunError);
    CHECK_THROWS_AS(elemForMP(m, Vector2d(5.0, 5.0), Vector2d(1e300, 0.4), e), RunError);
    // 4 x 2 cells, 5 x 3 = 15 nodes: still one point's
    CHECK(cellsOf(m, Vector2d(6.0, 5.0), Vector2d(1.9, 0.45)) ==
          std::vector<int>{44, 45, 46, 47, 54, 55, 56, 57});
  }
  TEST_CASE("elemForMP: a point outside the grid throws RunError") {
    const Mesh m = formCoord2D(4, 4, 4.0, 4.0);
    std::array<int, MAXE> e;
    CHECK_THROWS_AS(elemForMP(m, Vector2d(4.2, 1.0), Vector2d::Zero(), e), RunError);
    CHECK_THROWS_AS(elemForMP(m, Vector2d(1.0, -0.1), Vector2d(0.2, 0.2), e), RunError);
    CHECK_THROWS_AS(elemForMP(m, Vector2d(-0.5, 5.0), Vector2d::Zero(), e), RunError);
  }
  TEST_CASE("elemForMP: 6 x 3 cells of 0.5 x 2 from the origin x = -1.2 / y = 0.4: MPM and GIMP points") {
    // cell (i, j) is 6 j + i; vertical lines at -1.2 + 0.5 i, horizontal at 0.4 + 2 j
    Mesh m = formCoord2D(6, 3, 3.0, 6.0);
    m.origin = Vector2d(-1.2, 0.4);
    m.coord.rowwise() += m.origin.transpose();
    const Vector2d z = Vector2d::Zero();
    for (int rep = 0; rep < 2; ++rep) {
      CHECK(cellsOf(m, Vector2d(-0.05, 3.6), z) == std::vector<int>{8});     // inside (2, 1)
      CHECK(cellsOf(m, Vector2d(0.8, 5.4), z) == std::vector<int>{15});      // on x = 0.8: left
      CHECK(cellsOf(m, Vector2d(-0.95, 4.4), z) == std::vector<int>{6});     // on y = 4.4: below
      CHECK(cellsOf(m, Vector2d(-0.95, 4.4 + 1e-15), z) == std::vector<int>{6});
      CHECK(cellsOf(m, Vector2d(-0.95, 4.4 + 1e-6), z) == std::vector<int>{12});  // really above
      CHECK(cellsOf(m, Vector2d(0.8 - 1e-15, 2.4 + 1e-15), z) == std::vector<int>{3});  // a corner
      CHECK(cellsOf(m, Vector2d(0.8 + 1e-6, 2.4 + 1e-6), z) == std::vector<int>{10});
      CHECK(cellsOf(m, Vector2d(1.8, 6.4), z) == std::vector<int>{17});      // top right corner
      CHECK(cellsOf(m, Vector2d(-1.2, 0.4), z) == std::vector<int>{0});      // bottom left corner
      // GIMP: [0.75, 0.95] x [2.7, 3.3] across x = 0.8
      CHECK(cellsOf(m, Vector2d(0.85, 3.0), Vector2d(0.1, 0.3)) == std::vector<int>{9, 10});
      // [0.3, 0.8] x [2.4, 4.4] fills cell (3, 1) exactly
      CHECK(cellsOf(m, Vector2d(0.55, 3.4), Vector2d(0.25, 1.0)) == std::vector<int>{9});
      // [-0.5, -0.1] x [4.0, 4.6] across y = 4.4 (and inside columns 1, 2)
      CHECK(cellsOf(m, Vector2d(-0.3, 4.3), Vector2d(0.2, 0.3)) == std::vector<int>{7, 8, 13, 14});
      // [1.65, 1.85] x [0.35, 0.55]: past the right and bottom edges
      CHECK(cellsOf(m, Vector2d(1.75, 0.45), Vector2d(0.1, 0.1)) == std::vector<int>{5});
    }
  }
  TEST_CASE("elemForMP: the tolerance is in cell widths for cells of 1e4 and of 1e-3") {
    const Mesh big = formCoord2D(3, 2, 3e4, 2e4), small = formCoord2D(3, 2, 3e-3, 2e-3);
    const Vector2d z = Vector2d::Zero();
    for (int rep = 0; rep < 2; ++rep) {
      // 1e-7 on cells of 1e4 is 1e-11 cells: on the line x = 1e4, the cell to the left
      CHECK(cellsOf(big, Vector2d(1e4 + 1e-7, 5e3), z) == std::vector<int>{0});
      CHECK(cellsOf(big, Vector2d(1e4 + 1e-3, 5e3), z) == std::vector<int>{1});  // 1e-7 cells: right
      CHECK(cellsOf(big, Vector2d(5e3, 1e4 + 1e-7), z) == std::vector<int>{0});
      CHECK(cellsOf(big, Vector2d(2.5e4, 1e4 + 1e-3), z) == std::vector<int>{5});
      // 1e-10 on cells of 1e-3 is 1e-7 cells: right of the line x = 1e-3; 1e-15 is on it
      CHECK(cellsOf(small, Vector2d(1e-3 + 1e-10, 0.5e-3), z) == std::vector<int>{1});
      CHECK(cellsOf(small, Vector2d(1e-3 + 1e-15, 0.5e-3), z) == std::vector<int>{0});
      CHECK(cellsOf(small, Vector2d(2.5e-3, 1e-3 + 1e-10), z) == std::vector<int>{5});
      CHECK(cellsOf(small, Vector2d(2.5e-3, 1e-3 - 1e-16), z) == std::vector<int>{2});
      // GIMP: a domain overlapping a cell by 1e-7 cells has it; one touching it has not
      CHECK(cellsOf(small, Vector2d(1.5e-3, 0.5e-3), Vector2d(0.5e-3 + 1e-10, 0.2e-3)) ==
            std::vector<int>{0, 1, 2});
      CHECK(cellsOf(small, Vector2d(1.5e-3, 0.5e-3), Vector2d(0.5e-3, 0.2e-3)) == std::vector<int>{1});
      CHECK(cellsOf(big, Vector2d(1.5e4, 5e3), Vector2d(0.5e4 + 1e-7, 2e3)) == std::vector<int>{1});
      CHECK(cellsOf(big, Vector2d(1.5e4, 5e3), Vector2d(0.5e4 + 1e-3, 2e3)) == std::vector<int>{0, 1, 2});
    }
  }
  TEST_CASE("elemForMP: a GIMP domain narrower than the tolerance on a grid line has one cell") {
    const Mesh m = formCoord2D(4, 4, 4.0, 4.0);
    CHECK(cellsOf(m, Vector2d(2.0, 1.5), Vector2d(1e-12, 0.1)) == std::vector<int>{6});
    CHECK(cellsOf(m, Vector2d(1.5, 3.0), Vector2d(0.1, 1e-12)) == std::vector<int>{13});
  }
}

TEST_SUITE("nodesForMP") {
  TEST_CASE("nodesForMP: unique ascending nodes of 1 / 2 and 4 cells") {
    const Mesh m = formCoord2D(4, 4, 4.0, 4.0);  // 5 nodes per row
    CHECK(nodesOf(m, {5}) == std::vector<int>{6, 7, 11, 12});
    CHECK(nodesOf(m, {5, 6}) == std::vector<int>{6, 7, 8, 11, 12, 13});
    CHECK(nodesOf(m, {5, 9}) == std::vector<int>{6, 7, 11, 12, 16, 17});
    CHECK(nodesOf(m, {5, 6, 9, 10}) == std::vector<int>{6, 7, 8, 11, 12, 13, 16, 17, 18});
    const std::vector<int> n9 = nodesOf(m, {0, 1, 2, 4, 5, 6, 8, 9, 10});  // 3 x 3 cells
    REQUIRE(n9.size() == 16);
    for (size_t k = 1; k < n9.size(); ++k) CHECK(n9[k] > n9[k - 1]);
  }
}
