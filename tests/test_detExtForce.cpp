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
  mp.nn = int(nodes.size());
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
