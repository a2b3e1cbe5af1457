// Tests of solver=LDLT_HALVES (ample/solver/halvesLDLT.h): the split of the free dofs into
// two halves and an interface (a partition; no entry of K joins the halves; a straight grid
// line when the nodes' positions are given; balanced), the solve against a dense LU solve
// (Eigen's PartialPivLU, not the code under test) on grids of one and two cells' reach, with
// and without positions, a disconnected K and tiny ones; the same bits on one and two
// threads; a zero pivot in a half or in the interface reported; linSolve cutting the free
// dofs of a mesh where its nodes are.
#include "ample/linSolve.h"
#include "ample/solver/chosenSolve.h"
#include "ample/solver/halvesLDLT.h"
#include <doctest/doctest.h>
#include <Eigen/Dense>
#include <cmath>
#ifdef _OPENMP
#include <omp.h>
#endif

using namespace ample;
using Eigen::VectorXd;

namespace {
// a symmetric positive definite K on the (nx+1) x (ny+1) nodes of a grid of unit cells, two
// dofs a node (dof 2 node + i, nodes row by row); dofs of nodes at most `reach` cells apart
// in x and in y are coupled (1: bilinear cells, 2: GIMP-like domains); off-diagonal values
// -(0.1 + a smooth function of the pair), the diagonal 1 + the sum of their magnitudes
struct Grid {
  SpMat K;
  std::vector<Eigen::Vector2d> at;  // where each dof's node is
};
Grid grid(int nx, int ny, int reach) {
  const int nodes = (nx + 1) * (ny + 1), n = 2 * nodes;
  std::vector<Eigen::Triplet<double>> t;
  std::vector<double> diag(n, 1.0);
  Grid g;
  for (int a = 0; a < nodes; ++a) {
    const int ax = a % (nx + 1), ay = a / (nx + 1);
    for (int i = 0; i < 2; ++i) g.at.emplace_back(ax, ay);
    for (int b = 0; b < nodes; ++b) {
      const int bx = b % (nx + 1), by = b / (nx + 1);
      if (std::abs(ax - bx) > reach || std::abs(ay - by) > reach) continue;
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
          const int r = 2 * a + i, c = 2 * b + j;
          if (r >= c) continue;
          const double v = -(0.1 + 0.5 * std::abs(std::sin(0.37 * r + 0.11 * c)));
          t.emplace_back(r, c, v), t.emplace_back(c, r, v);
          diag[r] -= v, diag[c] -= v;
        }
    }
  }
  for (int r = 0; r < n; ++r) t.emplace_back(r, r, diag[r]);
  g.K = SpMat(n, n);
  g.K.setFromTriplets(t.begin(), t.end());
  return g;
}
VectorXd load(int n) {
  VectorXd b(n);
  for (int i = 0; i < n; ++i) b(i) = std::cos(0.3 * i) + 0.1 * i;
  return b;
}
// the split is a partition of 0 .. n-1 and no entry of K joins half 1 to half 2
bool validSplit(const SpMat& K, const std::array<std::vector<int>, 3>& split) {
  std::vector<int> where(K.rows(), -1);
  for (int part = 0; part < 3; ++part)
    for (int v : split[part]) {
      if (where[v] != -1) return false;
      where[v] = part;
    }
  for (int w : where)
    if (w < 0) return false;
  for (int c = 0; c < K.outerSize(); ++c)
    for (SpMat::InnerIterator it(K, c); it; ++it)
      if (where[it.row()] + where[c] == 1) return false;  // one in half 1 (0), one in half 2 (1)
  return true;
}
double relativeError(const VectorXd& x, const VectorXd& reference) {
  return (x - reference).norm() / reference.norm();
}
}  // namespace

TEST_SUITE("halvesLDLT") {
  TEST_CASE("splitInTwo: by position, a straight cut across the longer side: one grid line of bilinear cells, two of GIMP-like reach") {
    for (int reach : {1, 2}) {
      CAPTURE(reach);
      const Grid g = grid(30, 10, reach);                 // 31 x 11 nodes, longer in x
      const auto split = splitInTwo(g.K, g.at);
      CHECK(validSplit(g.K, split));
      CHECK(split[2].size() == size_t(2 * 11 * reach));   // reach lines of 11 nodes, 2 dofs each
      std::vector<double> xs;
      for (int v : split[2]) xs.push_back(g.at[v](0));
      CHECK(*std::max_element(xs.begin(), xs.end()) - *std::min_element(xs.begin(), xs.end()) == reach - 1);
      const double n = double(g.K.rows());
      CHECK(split[0].size() >= 0.4 * n);
      CHECK(split[1].size() >= 0.4 * n);
    }
    const Grid tall = grid(6, 20, 1);                     // longer in y: a line of 7 nodes
    const auto split = splitInTwo(tall.K, tall.at);
    CHECK(validSplit(tall.K, split));
    CHECK(split[2].size() == 14);
  }

  TEST_CASE("splitInTwo: by K's graph alone, a level of a breadth-first structure: a partition, no entry between the halves, balanced") {
    for (int reach : {1, 2}) {
      CAPTURE(reach);
      const Grid g = grid(24, 8, reach);
      const auto split = splitInTwo(g.K);
      CHECK(validSplit(g.K, split));
      const double n = double(g.K.rows());
      CHECK(split[0].size() >= 0.3 * n);
      CHECK(split[1].size() >= 0.3 * n);
      CHECK(split[2].size() <= 0.2 * n);
    }
    SpMat one(2, 2);                                      // two coupled dofs: no level inside
    one.insert(0, 0) = 2, one.insert(1, 0) = -1, one.insert(0, 1) = -1, one.insert(1, 1) = 2;
    one.makeCompressed();
    const auto tiny = splitInTwo(one);
    CHECK(validSplit(one, tiny));
    CHECK(tiny[0].size() == 2);
    CHECK(tiny[2].empty());
  }

  TEST_CASE("HalvesLDLT: K x = b as a dense LU solves it, to 1e-12, on grids of reach 1 and 2, with and without positions") {
    for (int reach : {1, 2})
      for (bool positions : {true, false}) {
        CAPTURE(reach);
        CAPTURE(positions);
        const Grid g = grid(20, 9, reach);
        const VectorXd b = load(int(g.K.rows()));
        const VectorXd reference = Eigen::PartialPivLU<Eigen::MatrixXd>(Eigen::MatrixXd(g.K)).solve(b);
        HalvesLDLT h;
        h.analyzePattern(g.K, positions ? g.at : std::vector<Eigen::Vector2d>{});
        h.factorize(g.K);
        REQUIRE(h.info() == Eigen::Success);
        CHECK(h.interfaceSize() > 0);
        CHECK(h.halfSize(0) + h.halfSize(1) + h.interfaceSize() == g.K.rows());
        CHECK(relativeError(h.solve(b), reference) <= 1e-12);
        SpMat K2 = g.K;                                   // new values, the same pattern: no analysis
        K2.coeffs() *= 3.0;
        h.factorize(K2);
        CHECK(relativeError(h.solve(b), reference / 3.0) <= 1e-12);
      }
  }

  TEST_CASE("HalvesLDLT: a disconnected K (two grids), a 2 x 2 K and a 1 x 1 K solve as a dense LU does") {
    const Grid a = grid(5, 3, 1), b = grid(4, 4, 2);
    const int na = int(a.K.rows()), n = na + int(b.K.rows());
    std::vector<Eigen::Triplet<double>> t;
    for (const auto* part : {&a, &b})
      for (int c = 0; c < part->K.outerSize(); ++c)
        for (SpMat::InnerIterator it(part->K, c); it; ++it)
          t.emplace_back(it.row() + (part == &b ? na : 0), c + (part == &b ? na : 0), it.value());
    SpMat K(n, n);
    K.setFromTriplets(t.begin(), t.end());
    SpMat two(2, 2), one(1, 1);
    two.insert(0, 0) = 2, two.insert(1, 0) = -1, two.insert(0, 1) = -1, two.insert(1, 1) = 3;
    one.insert(0, 0) = 4;
    two.makeCompressed(), one.makeCompressed();           // (as Kt(fd,fd) comes)
    for (const SpMat* M : {&K, &two, &one}) {
      CAPTURE(M->rows());
      const VectorXd f = load(int(M->rows()));
      HalvesLDLT h;
      h.analyzePattern(*M);
      h.factorize(*M);
      REQUIRE(h.info() == Eigen::Success);
      CHECK(relativeError(h.solve(f), Eigen::PartialPivLU<Eigen::MatrixXd>(Eigen::MatrixXd(*M)).solve(f)) <= 1e-12);
    }
  }

  TEST_CASE("HalvesLDLT: one and two threads give the same solution bit for bit") {
#ifndef _OPENMP
    MESSAGE("built without AMPLE_OPENMP: the halves run one after the other, nothing to compare");
#else
    const Grid g = grid(40, 12, 2);
    const VectorXd b = load(int(g.K.rows()));
    const int before = omp_get_max_threads();
    VectorXd x[2];
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      HalvesLDLT h;
      h.analyzePattern(g.K, g.at);
      h.factorize(g.K);
      x[threads - 1] = h.solve(b);
    }
    omp_set_num_threads(before);
    CHECK(x[0].size() == g.K.rows());
    CHECK((x[0].array() == x[1].array()).all());
#endif
  }

  TEST_CASE("HalvesLDLT: a dof without stiffness (a zero pivot) in a half or in the interface: info() is NumericalIssue") {
    const Grid g = grid(12, 5, 1);
    const auto split = splitInTwo(g.K, g.at);
    for (int part : {0, 1, 2}) {
      CAPTURE(part);
      const int dead = split[part][split[part].size() / 2];
      SpMat K = g.K;                                      // the same pattern, row and column zero
      for (int c = 0; c < K.outerSize(); ++c)
        for (SpMat::InnerIterator it(K, c); it; ++it)
          if (it.row() == dead || c == dead) it.valueRef() = 0.0;
      HalvesLDLT h;
      h.analyzePattern(K, g.at);
      h.factorize(K);
      CHECK(h.info() == Eigen::NumericalIssue);
    }
  }

  TEST_CASE("linSolve: solver=LDLT_HALVES with the nodes' coordinates cuts the free dofs along a grid line, and solves as SparseLU") {
    const Grid g = grid(30, 10, 1);                       // dof 2 node + i, as the mesh numbers them
    Eigen::Matrix<double, Eigen::Dynamic, nD, Eigen::RowMajor> coord(g.K.rows() / 2, 2);
    for (int a = 0; a < coord.rows(); ++a) coord.row(a) = g.at[2 * a].transpose();
    std::vector<int> fd;                                  // the left column of nodes held
    for (int d = 0; d < g.K.rows(); ++d)
      if (g.at[d](0) > 0) fd.push_back(d);
    const VectorXd oobf = load(int(g.K.rows()));
    FreeSystem lu, halves;
    halves.choice = LinearSolver::LDLT_HALVES;
    halves.nodeCoord = &coord;
    const LinSolveOut a = chosenSolve(lu, {}, g.K, oobf, 2, fd), b = chosenSolve(halves, {}, g.K, oobf, 2, fd);
    CHECK(halves.halves.interfaceSize() == 22);           // one line of 11 nodes
    CHECK(halves.fallbacks == 0);
    CHECK(relativeError(b.duvw, a.duvw) <= 1e-12);
  }
}
