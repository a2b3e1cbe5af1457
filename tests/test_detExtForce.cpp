// Tests of detExtForce ([AMPLE] eqs 27-28, 32): f_ext = sum_p S_vp (m_p {0,-g} + f_p).
// The points are made by hand (nodes, basis values, mass, point force), so only
// detExtForce itself is exercised.
#include "ample/detExtForce.h"
#include <doctest/doctest.h>
#include <cmath>

using namespace ample;

namespace {
// a point linked to nodes `nodes` with basis values `S` (summing to 1)
MaterialPoint point(std::vector<int> nodes, std::vector<double> S, double m, Vector2d fp) {
  MaterialPoint mp;
  mp.nn = int(nodes.size());  // nn and room for the nodes and values
  for (int v = 0; v < mp.nn; ++v) {
    mp.nIN[v] = nodes[v];
    mp.Svp[v] = S[v];
  }
  mp.mpM = m;
  mp.fp = fp;
  return mp;
}
const double g = 9.81;
}  // namespace

TEST_SUITE("detExtForce") {
  TEST_CASE("detExtForce: total force = -sum(m g) in y plus the sum of the point forces") {
    const std::vector<MaterialPoint> pts = {
        point({0, 1, 3, 4}, {0.1, 0.2, 0.3, 0.4}, 2.0, Vector2d(0, 0)),
        point({1, 2, 4, 5}, {0.25, 0.25, 0.25, 0.25}, 3.0, Vector2d(40.0, -7.0)),
        point({0, 1, 2, 3, 4, 5}, {0.05, 0.15, 0.1, 0.2, 0.3, 0.2}, 1.5, Vector2d(-5.0, 12.0))};
    const Eigen::VectorXd f = detExtForce(14, g, pts);  // 7 nodes, node 6 unused
    REQUIRE(f.size() == 14);
    double fx = 0, fy = 0;
    for (int n = 0; n < 7; ++n) {
      fx += f(dof(n, 0));
      fy += f(dof(n, 1));
    }
    CHECK(fx == doctest::Approx(40.0 - 5.0).epsilon(1e-14));
    CHECK(fy == doctest::Approx(-(2.0 + 3.0 + 1.5) * g - 7.0 + 12.0).epsilon(1e-14));
    CHECK(f(dof(6, 0)) == 0.0);
    CHECK(f(dof(6, 1)) == 0.0);
  }
  TEST_CASE("detExtForce: weight and point force are spread over the nodes by S_vp") {
    const Vector2d fp(30.0, -50.0);
    const MaterialPoint p = point({2, 3, 7, 8}, {0.12, 0.28, 0.18, 0.42}, 4.0, fp);
    const Eigen::VectorXd f = detExtForce(20, g, {p});
    for (int v = 0; v < p.nn; ++v) {
      CAPTURE(v);
      CHECK(f(dof(p.nIN[v], 0)) == doctest::Approx(p.Svp[v] * fp(0)).epsilon(1e-14));
      CHECK(f(dof(p.nIN[v], 1)) == doctest::Approx(p.Svp[v] * (fp(1) - 4.0 * g)).epsilon(1e-14));
    }
    double rest = 0;  // nothing anywhere else
    for (int n : {0, 1, 4, 5, 6, 9}) rest += f.segment<2>(2 * n).norm();
    CHECK(rest == 0.0);
  }
  TEST_CASE("detExtForce: without gravity only the point forces remain / g scales the weight") {
    const MaterialPoint p = point({0, 1}, {0.3, 0.7}, 5.0, Vector2d(0, 0));
    CHECK(detExtForce(4, 0.0, {p}).norm() == 0.0);
    const Eigen::VectorXd f1 = detExtForce(4, 1.0, {p}), f2 = detExtForce(4, 2.0, {p});
    CHECK((f2 - 2.0 * f1).norm() <= 1e-14);
    CHECK(f1(dof(1, 1)) == doctest::Approx(-0.7 * 5.0).epsilon(1e-14));  // gravity acts in -y
    CHECK(f1(dof(1, 0)) == 0.0);
  }
}

TEST_SUITE("detExtForce") {
  // two point sets on different grids, called in turn: each result from its own input only
  // (an answer that keeps an earlier call's vector, or its size, fails)
  TEST_CASE("detExtForce: two point sets with two g and two sizes in turn: the nodal forces by hand each time") {
    // set 1: a GIMP point of 9 nodes (0.1225 0.855 0.0225 in x and y) on a 3 x 3 node grid
    const double s[3] = {0.1225, 0.855, 0.0225};
    std::vector<int> nodes;
    std::vector<double> S;
    for (int b = 0; b < 3; ++b)
      for (int a = 0; a < 3; ++a) {
        nodes.push_back(3 * b + a);
        S.push_back(s[a] * s[b]);
      }
    const std::vector<MaterialPoint> set1 = {point(nodes, S, 2.5, Vector2d(10.0, 4.0))};
    // set 2: two MPM points on a 4-node-wide grid sharing nodes 5 and 6, nodes 9.. unused
    const std::vector<MaterialPoint> set2 = {point({1, 2, 5, 6}, {0.2, 0.3, 0.1, 0.4}, 1.0, Vector2d(0, 0)),
                                             point({5, 6, 9, 10}, {0.5, 0.25, 0.125, 0.125}, 4.0, Vector2d(-8.0, 0))};
    for (int round = 0; round < 2; ++round) {
      CAPTURE(round);
      const Eigen::VectorXd f1 = detExtForce(18, 9.81, set1);
      REQUIRE(f1.size() == 18);
      for (int v = 0; v < 9; ++v) {
        CHECK(f1(2 * v) == doctest::Approx(S[v] * 10.0).epsilon(1e-14));
        CHECK(f1(2 * v + 1) == doctest::Approx(S[v] * (4.0 - 2.5 * 9.81)).epsilon(1e-14));
      }
      const Eigen::VectorXd f2 = detExtForce(32, 2.0, set2);
      REQUIRE(f2.size() == 32);
      Eigen::VectorXd e2 = Eigen::VectorXd::Zero(32);   // by hand: y = -m g S, x = fp_x S
      e2(2 * 1 + 1) = -0.2 * 2.0, e2(2 * 2 + 1) = -0.3 * 2.0;
      e2(2 * 5 + 1) = -0.1 * 2.0 - 0.5 * 8.0, e2(2 * 6 + 1) = -0.4 * 2.0 - 0.25 * 8.0;
      e2(2 * 9 + 1) = -0.125 * 8.0, e2(2 * 10 + 1) = -0.125 * 8.0;
      e2(2 * 5) = -0.5 * 8.0, e2(2 * 6) = -0.25 * 8.0, e2(2 * 9) = -0.125 * 8.0, e2(2 * 10) = -0.125 * 8.0;
      CHECK((f2 - e2).norm() <= 1e-14 * e2.norm());
    }
  }
  TEST_CASE("detExtForce: additive over the points / a node's force sums its points' shares / the total moment sum_v x_v f_v = sum_p x_p F_p") {
    // nodes of a 3 x 3 grid of 1 m cells (node n = 4 row + column); each point's basis
    // values reproduce its position (sum_v S_v x_v = x_p), so the moment of the nodal forces
    // is that of the point forces
    auto X = [](int n) { return Vector2d(n % 4, n / 4); };
    const MaterialPoint a = point({0, 1, 4, 5}, {0.28, 0.42, 0.12, 0.18}, 3.0, Vector2d(1.0, 2.0));    // at (0.6, 0.3)
    const MaterialPoint b = point({5, 6, 9, 10}, {0.06, 0.14, 0.24, 0.56}, 1.5, Vector2d(-4.0, 0.5));  // at (1.7, 1.8)
    const Eigen::VectorXd fa = detExtForce(32, 3.0, {a}), fb = detExtForce(32, 3.0, {b});
    const Eigen::VectorXd fab = detExtForce(32, 3.0, {a, b});
    CHECK((fab - fa - fb).norm() <= 1e-14 * fab.norm());
    CHECK(fab(2 * 5 + 1) == doctest::Approx(0.18 * (2.0 - 9.0) + 0.06 * (0.5 - 4.5)).epsilon(1e-14));
    double moment = 0.0;  // about the origin, z component: x f_y - y f_x
    for (int n = 0; n < 16; ++n) moment += X(n)(0) * fab(2 * n + 1) - X(n)(1) * fab(2 * n);
    const double expected = 0.6 * (2.0 - 9.0) - 0.3 * 1.0 + 1.7 * (0.5 - 4.5) - 1.8 * (-4.0);
    CHECK(moment == doctest::Approx(expected).epsilon(1e-13));
  }
}
