// Tests of the moving and curved implicit boundaries of [Boundaries] secs 5.5-5.6:
// setups footing (a Prescribed segment pushed through the grid) and funnel
// (curved rollers, a PrescribedNormal edge). References: linearity of the small
// strain problem, the prescribed values read back from the nodal field by a
// bilinear interpolation written here, and equilibrium of the boundary forces.
#include "ample/errors.h"
#include "ample/boundaries/ibStiffness.h"
#include "testProblems.h"

using namespace ample;

namespace {
// the grid field uvw at x, by the bilinear interpolation of the cell that holds x
Vector2d interpolate(const Mesh& mesh, const Eigen::VectorXd& uvw, const Vector2d& x) {
  const Vector2d s = (x - mesh.coord.row(0).transpose()).cwiseQuotient(mesh.h);
  const int ix = int(std::floor(s(0))), iy = int(std::floor(s(1)));
  const double xi = s(0) - ix, eta = s(1) - iy;
  const int e = iy * mesh.nelsx + ix;
  const double N[4] = {(1 - xi) * (1 - eta), xi * (1 - eta), xi * eta, (1 - xi) * eta};
  Vector2d u = Vector2d::Zero();
  for (int j = 0; j < 4; ++j) {
    const int n = mesh.etpl(e, j);
    REQUIRE((mesh.coord.row(n).transpose() - (mesh.coord.row(0).transpose() +
             Vector2d(ix + (j == 1 || j == 2), iy + (j >= 2)).cwiseProduct(mesh.h))).norm() < 1e-12);
    u += N[j] * Vector2d(uvw(2 * n), uvw(2 * n + 1));
  }
  return u;
}
}  // namespace

TEST_SUITE("ibMoving") {
  TEST_CASE("footing: one small-strain step is linear in the push and holds the footing's value") {
    double load[2];
    for (int k = 0; k < 2; ++k) {
      RunLog log;
      const double push = 0.05 * (k + 1);
      const Analysis an = testing::runSetup("footing", {{"lstps", 1}, {"push", push}}, log);
      REQUIRE(log.converged);
      load[k] = an.history.back()[2].second;
      // the footing (y = 3.2 m, x in [1.2, 2.2] m before it moved) and the base (y = 0.2 m)
      double footErr = 0, baseErr = 0;
      for (double x = 1.25; x < 2.2; x += 0.1) {
        footErr = std::max(footErr, (interpolate(an.mesh, an.uvw, {x, 3.2 - 1e-9}) -
                                     Vector2d(0, -push)).norm() / push);
        baseErr = std::max(baseErr, interpolate(an.mesh, an.uvw, {x, 0.2 + 1e-9}).norm() / push);
      }
      CHECK(footErr < 1e-5);  // the band and K2 coupling: O(delta / h) = 1e-6
      CHECK(baseErr < 1e-5);
      CHECK(an.history.back()[3].second < 1e-8 * load[k] * 1e3);  // forces in balance (N/m)
    }
    CHECK(std::abs(load[1] / load[0] - 2) < 1e-8);   // small strain, one step: linear
  }

  TEST_CASE("footing: 20 steps in SS and UL, forces in balance at every step") {
    for (int f : {3, 1}) {
      RunLog log;
      const Analysis an = testing::runSetup("footing", {{"formulation", f}}, log);
      REQUIRE(log.converged);
      double prev = 0;
      for (const auto& row : an.history) {
        CHECK(row[2].second > prev);                    // the load grows with the settlement
        CHECK(row[3].second < 1e-8 * row[2].second * 1e3);
        prev = row[2].second;
      }
    }
  }

  TEST_CASE("footing: a footing above every point stops the run with a message, not a zero load") {
    // h = 0.5 m: in step 9 the footing (y = 3.1 m) cuts only the cells above the points,
    // which have moved below y = 3.0 m; the paper's method has nothing to push there
    RunLog log;
    CHECK_THROWS_WITH_AS(testing::runSetup("footing", {{"h", 0.5}}, log),
                         doctest::Contains("cuts no cell that holds a material point in load step 9"),
                         RunError);
    CHECK(log.steps.size() == 8);
  }

  TEST_CASE("funnel: with the segments' normals no point leaves the walls") {
    // the paper's statement of sec 5.6; with the curve's normals points on the convex part
    // leave by about kappa s^2 / 2 per step (docs/implicitBoundaries.md)
    RunLog log;
    const Analysis an = testing::runSetup("funnel", {{"normals", 0}, {"h", 2e-3}}, log);
    REQUIRE(log.converged);
    REQUIRE(an.history.size() == 6);
    for (const auto& row : an.history) CHECK(row[2].second == 0.0);
  }

  TEST_CASE("funnel: the walls and the pushed edge are in balance") {
    RunLog log;
    const Analysis an = testing::runSetup("funnel", {{"h", 2e-3}, {"lstps", 2}}, log);
    REQUIRE(log.converged);
    Vector2d sum = Vector2d::Zero();
    for (const Vector2d& f : an.ibForce) sum += f;
    CHECK(sum.norm() < 1e-7 * an.ibForce[1].norm());
    CHECK(an.ibForce[1](0) < 0);                      // the edge pushes to the left
  }
}
