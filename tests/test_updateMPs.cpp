// Tests of updateMPs ([AMPLE] sec 3.4, eqs 15, 33, 34) and of stretchTensor.
// The points are made by hand on a single 1 m cell (nodes 0-3, basis values,
// F), so only updateMPs itself is exercised; domains use the default
// DomainUpdate::Uii (eq 34). The other domain updates: tests/test_updateDomain.cpp.
#include "ample/meshes/formCoord2D.h"
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
  updateMPs(cell, uvw, DomainUpdate::Uii, pts);
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
  mp.nn = 4;
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
