// Tests of updateMPs ([AMPLE] sec 3.4, eqs 15, 33, 34) and of stretchTensor.
// The points are made by hand on a single 1 m cell (nodes 0-3, basis values,
// F), so only updateMPs itself is exercised; domains use the default
// DomainUpdate::Uii (eq 34). The other domain updates: tests/test_updateDomain.cpp.
#include "setups/formCoord2D.h"
#include "ample/stiffness/tensorOps.h"
#include "ample/updateMPs.h"
#include <doctest/doctest.h>
#include <Eigen/Eigenvalues>
#include <cmath>

using namespace ample;

namespace {
const Mesh cell = formCoord2D(1, 1, 1.0, 1.0);  // nodes 0-3, 8 dofs

// the update of eq 34 (GIMP l_i = l0_i U_ii)
void update(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& pts) {
  updateMPs(cell, uvw, pts);
}

Matrix3d rotationZ(double a) {
  Matrix3d R;
  R << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  return R;
}

// a point linked to nodes 0..3 with the given basis values and deformation gradient
MaterialPoint point(MpType t, const Vector2d& x, const std::array<double, 4>& S, const Matrix3d& F) {
  MaterialPoint mp;
  mp.mpType = t;
  mp.mpC = mp.X0 = x;
  mp.u = Vector2d(0.01, -0.02);  // displacement of earlier steps
  mp.vp0 = 0.0625;
  mp.vp = 0.07;
  mp.lp0 = (t == MpType::GIMP) ? Vector2d(0.125, 0.125) : Vector2d::Zero();
  mp.lp = mp.lp0;
  mp.nn = 4;           // nn = 4 and room for the basis
  for (int v = 0; v < 4; ++v) {
    mp.nIN[v] = v;
    mp.Svp[v] = S[v];
  }
  mp.F = F;
  mp.epsE << 1e-3, -2e-3, 0, 5e-4, 0, 0;
  return mp;
}
}  // namespace

TEST_SUITE("updateMPs") {
  TEST_CASE("stretchTensor: U symmetric positive definite / U U = F'F / R = F U^-1 a rotation") {
    Matrix3d F;
    F << 1.2, 0.4, 0, -0.3, 0.9, 0, 0, 0, 1.1;
    const Matrix3d U = stretchTensor(F), R = F * U.inverse();
    CHECK((U - U.transpose()).norm() <= 1e-14);
    CHECK(Eigen::SelfAdjointEigenSolver<Matrix3d>(U).eigenvalues().minCoeff() > 0.0);
    CHECK((U * U - F.transpose() * F).norm() <= 1e-13);
    CHECK((R.transpose() * R - Matrix3d::Identity()).norm() <= 1e-13);
    CHECK(R.determinant() == doctest::Approx(1.0).epsilon(1e-13));  // proper rotation
  }
  TEST_CASE("stretchTensor: a rotation has U = I / a rotated stretch gives the stretch back") {
    CHECK((stretchTensor(rotationZ(0.6)) - Matrix3d::Identity()).norm() <= 1e-14);
    const Matrix3d U0 = Vector3d(1.3, 0.8, 1.0).asDiagonal();
    CHECK((stretchTensor(rotationZ(-1.1) * U0) - U0).norm() <= 1e-14);
  }
  TEST_CASE("updateMPs: a uniform nodal displacement moves every point by exactly it") {
    const Vector2d a(0.05, -0.03);
    Eigen::VectorXd uvw(8);
    for (int n = 0; n < 4; ++n) uvw.segment<2>(2 * n) = a;
    for (MpType t : {MpType::MPM, MpType::GIMP}) {
      std::vector<MaterialPoint> pts = {
          point(t, Vector2d(0.3, 0.4), {0.42, 0.18, 0.28, 0.12}, Matrix3d::Identity()),
          point(t, Vector2d(0.9, 0.1), {0.09, 0.81, 0.01, 0.09}, Matrix3d::Identity())};
      const std::vector<MaterialPoint> before = pts;
      update(uvw, pts);
      for (size_t p = 0; p < pts.size(); ++p) {
        CHECK((pts[p].mpC - (before[p].mpC + a)).norm() <= 1e-15);
        CHECK((pts[p].u - (before[p].u + a)).norm() <= 1e-15);  // total displacement
      }
    }
  }
  TEST_CASE("updateMPs: position moves by sum_v S_vp du_v (eq 33)") {
    Eigen::VectorXd uvw(8);
    uvw << 0.1, 0.0, -0.2, 0.05, 0.3, 0.1, 0.0, -0.4;
    const std::array<double, 4> S = {0.1, 0.2, 0.3, 0.4};
    std::vector<MaterialPoint> pts = {point(MpType::MPM, Vector2d(0.5, 0.5), S, Matrix3d::Identity())};
    update(uvw, pts);
    const Vector2d du(0.1 * 0.1 - 0.2 * 0.2 + 0.3 * 0.3, 0.2 * 0.05 + 0.3 * 0.1 - 0.4 * 0.4);
    CHECK((pts[0].mpC - (Vector2d(0.5, 0.5) + du)).norm() <= 1e-15);
  }
  TEST_CASE("updateMPs: vp = det(F) vp0 / GIMP lp = lp0 U_ii / MPM lp stays 0 / state stored") {
    Matrix3d F;
    F << 1.1, 0.2, 0, -0.05, 0.85, 0, 0, 0, 1;
    const Matrix3d U = stretchTensor(F);
    const Eigen::VectorXd uvw = Eigen::VectorXd::Zero(8);
    for (MpType t : {MpType::MPM, MpType::GIMP}) {
      CAPTURE(int(t));
      std::vector<MaterialPoint> pts = {point(t, Vector2d(0.5, 0.5), {0.25, 0.25, 0.25, 0.25}, F)};
      const MaterialPoint a = pts[0];
      update(uvw, pts);
      const MaterialPoint& b = pts[0];
      CHECK(b.vp == doctest::Approx(F.determinant() * a.vp0).epsilon(1e-14));  // not det(F) vp
      if (t == MpType::GIMP) {
        CHECK(b.lp(0) == doctest::Approx(a.lp0(0) * U(0, 0)).epsilon(1e-14));
        CHECK(b.lp(1) == doctest::Approx(a.lp0(1) * U(1, 1)).epsilon(1e-14));
      } else {
        CHECK(b.lp == Vector2d::Zero());
      }
      CHECK(b.Fn == F);  // converged state for the next step
      CHECK(b.epsEn == a.epsE);
      CHECK(b.mpC == a.mpC);  // no displacement, no movement
    }
  }
  TEST_CASE("updateMPs: a rigid rotation leaves GIMP domains and volumes unchanged") {
    std::vector<MaterialPoint> pts = {
        point(MpType::GIMP, Vector2d(0.5, 0.5), {0.25, 0.25, 0.25, 0.25}, rotationZ(0.5))};
    update(Eigen::VectorXd::Zero(8), pts);
    CHECK((pts[0].lp - Vector2d(0.125, 0.125)).norm() <= 1e-15);  // U = I, though F_ii = cos 0.5
    CHECK(pts[0].vp == doctest::Approx(0.0625).epsilon(1e-14));
  }
}

TEST_SUITE("updateMPs") {
  // a 2 x 2 grid of 1 m cells (node n = 3 row + column): points linked to nodes other than
  // 0..3, listed in any order, a 9-node GIMP point, and two load steps in turn
  const Mesh grid = formCoord2D(2, 2, 2.0, 2.0);
  Eigen::VectorXd gridUvw(double scale) {
    Eigen::VectorXd u(18);
    for (int d = 0; d < 18; ++d) u(d) = scale * (0.01 * (d + 1) * (d % 2 ? -1 : 1) + 0.003 * d * d);
    return u;
  }
  MaterialPoint gridPoint(MpType t, std::vector<int> nodes, std::vector<double> S, const Matrix3d& F) {
    MaterialPoint mp;
    mp.mpType = t;
    mp.vp0 = 0.25;
    mp.vp = 0.3;
    mp.lp0 = mp.lp = (t == MpType::GIMP) ? Vector2d(0.25, 0.25) : Vector2d::Zero();
    mp.nn = int(nodes.size());
    Vector2d x = Vector2d::Zero();
    for (int v = 0; v < mp.nn; ++v) {
      mp.nIN[v] = nodes[v];
      mp.Svp[v] = S[v];
      x += S[v] * Vector2d(nodes[v] % 3, nodes[v] / 3);
    }
    mp.mpC = mp.X0 = x;
    mp.F = F;
    return mp;
  }

  TEST_CASE("updateMPs: points on nodes 4..8 in any order and a 9-node GIMP point move by sum_v S_v u_v (by hand) over two steps") {
    // MPM point at (1.7, 1.4) in cell 3: nodes 8 4 7 5 listed out of order, S bilinear
    const MaterialPoint a = gridPoint(MpType::MPM, {8, 4, 7, 5}, {0.28, 0.18, 0.12, 0.42}, Matrix3d::Identity());
    // GIMP point at (1.1, 0.9), l = 0.25: S = Sx Sy with 0.0225 0.855 0.1225 (x) and 0.1225 0.855 0.0225 (y)
    const double sx[3] = {0.0225, 0.855, 0.1225}, sy[3] = {0.1225, 0.855, 0.0225};
    std::vector<int> nodes;
    std::vector<double> S;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) nodes.push_back(3 * r + c), S.push_back(sx[c] * sy[r]);
    const MaterialPoint b = gridPoint(MpType::GIMP, nodes, S, Matrix3d::Identity());
    REQUIRE((a.mpC - Vector2d(1.7, 1.4)).norm() <= 1e-14);
    REQUIRE((b.mpC - Vector2d(1.1, 0.9)).norm() <= 1e-14);
    std::vector<MaterialPoint> pts = {a, b};
    Vector2d ua = Vector2d::Zero(), ub = Vector2d::Zero();  // displacements of the steps, by hand
    for (double scale : {1.0, -0.5}) {
      CAPTURE(scale);
      const Eigen::VectorXd u = gridUvw(scale);
      Vector2d da = Vector2d::Zero(), db = Vector2d::Zero();
      for (int v = 0; v < 4; ++v) da += a.Svp[v] * Vector2d(u(2 * a.nIN[v]), u(2 * a.nIN[v] + 1));
      for (int v = 0; v < 9; ++v) db += S[v] * Vector2d(u(2 * nodes[v]), u(2 * nodes[v] + 1));
      ua += da, ub += db;
      updateMPs(grid, u, pts);
      CHECK((pts[0].mpC - (a.mpC + ua)).norm() <= 1e-14);
      CHECK((pts[1].mpC - (b.mpC + ub)).norm() <= 1e-14);
      CHECK((pts[0].u - ua).norm() <= 1e-14);
      CHECK((pts[1].u - ub).norm() <= 1e-14);
    }
    // and the sums are not trivial: the point moved by something else than node 0's u
    CHECK(ua.norm() > 1e-3);
  }
  TEST_CASE("updateMPs: two points with their own F over two steps: vp = det(F) vp0 and Fn = F of each step / never compounded") {
    Matrix3d F1, F2, G1, G2;
    F1 << 1.1, 0.2, 0, -0.05, 0.85, 0, 0, 0, 1;
    F2 << 1.2, 0.25, 0, -0.1, 0.8, 0, 0, 0, 1;
    G1 << 0.9, 0, 0, 0.1, 1.05, 0, 0, 0, 1;
    G2 << 0.95, -0.1, 0, 0.15, 1.1, 0, 0, 0, 1;
    std::vector<MaterialPoint> pts = {gridPoint(MpType::GIMP, {0, 1, 3, 4}, {0.25, 0.25, 0.25, 0.25}, F1),
                                      gridPoint(MpType::MPM, {4, 5, 7, 8}, {0.1, 0.2, 0.3, 0.4}, G1)};
    pts[0].epsE << 1e-3, 0, 0, 0, 0, 0;
    pts[1].epsE << 0, 2e-3, 0, 0, 0, 0;
    updateMPs(grid, Eigen::VectorXd::Zero(18), pts);
    CHECK(pts[0].vp == doctest::Approx(0.25 * (1.1 * 0.85 + 0.2 * 0.05)).epsilon(1e-14));   // det F1 = 0.945
    CHECK(pts[1].vp == doctest::Approx(0.25 * 0.9 * 1.05).epsilon(1e-14));                   // det G1 = 0.945
    CHECK(pts[0].Fn == F1);
    CHECK(pts[1].Fn == G1);
    CHECK(pts[0].epsEn(0) == 1e-3);
    CHECK(pts[1].epsEn(1) == 2e-3);
    // step 2: new F and strains; the volume from vp0, not from the last vp
    pts[0].F = F2, pts[1].F = G2;
    pts[0].epsE << 0, 0, 0, 5e-4, 0, 0;
    pts[1].epsE << 0, 0, -7e-4, 0, 0, 0;
    updateMPs(grid, Eigen::VectorXd::Zero(18), pts);
    CHECK(pts[0].vp == doctest::Approx(0.25 * (1.2 * 0.8 + 0.25 * 0.1)).epsilon(1e-14));    // det F2 = 0.985
    CHECK(pts[1].vp == doctest::Approx(0.25 * (0.95 * 1.1 + 0.1 * 0.15)).epsilon(1e-14));   // det G2 = 1.06
    CHECK(pts[0].Fn == F2);
    CHECK(pts[1].Fn == G2);
    CHECK(pts[0].F == F2);                                  // F itself is left as it was
    CHECK(pts[0].epsEn(3) == 5e-4);
    CHECK(pts[1].epsEn(2) == -7e-4);
    CHECK(pts[0].epsEn(0) == 0.0);
  }
}
