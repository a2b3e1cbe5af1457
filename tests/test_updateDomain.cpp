// Tests of updateDomain: the suitability pattern of [Lagrangian] table 2 for the
// GIMP domain updates (eqs 32-39) under four homogeneous deformation modes, and
// the CPDI1 / CPDI2 domain updates ([CPDI] sec 2 (vii)). A domain update is
// "correct" when the domain area 4 lx ly equals det(F) V0 and, for the stretch
// and hydrostatic modes, when the half lengths equal l0 times the stretches.
#include "ample/cpdi/domainCorners.h"
#include "ample/cpdi/elemMPinfoCPDI.h"
#include "ample/elemMPinfo.h"
#include "setups/formCoord2D.h"
#include "ample/domains/updateDomain.h"
#include "ample/stiffness/tensorOps.h"
#include "ample/updateMPs.h"
#include <doctest/doctest.h>
#include <cmath>
#include <string>

using namespace ample;

namespace {
const double pi = 3.14159265358979323846;
const double tolOK = 1e-12, tolBad = 1e-3;  // a tick: error <= 1e-12; a cross: error > 1e-3

struct Mode {
  std::string name;
  Eigen::Matrix2d F;
  bool checkLengths;  // stretch and hydrostatic: the lengths are known (l0 * F_ii)
};
std::vector<Mode> modes() {
  const double c = std::cos(pi / 3), s = std::sin(pi / 3);
  Eigen::Matrix2d st, hy, sh, ro;
  st << 1.5, 0, 0, 1;
  hy << 1.2, 0, 0, 1.2;
  sh << 1, 1, 0, 1;
  ro << c, -s, s, c;
  return {{"stretch", st, true}, {"hydrostatic", hy, true}, {"shear", sh, false}, {"rotation", ro, false}};
}

Matrix3d F3(const Eigen::Matrix2d& F) {
  Matrix3d G = Matrix3d::Identity();
  G.topLeftCorner<2, 2>() = F;
  return G;
}

// uvw of the homogeneous field x = F X at every node
Eigen::VectorXd homogeneousUvw(const Mesh& mesh, const Eigen::Matrix2d& F) {
  Eigen::VectorXd uvw(mesh.nDoF());
  for (int n = 0; n < mesh.nodes(); ++n)
    uvw.segment<2>(dof(n, 0)) = (F - Eigen::Matrix2d::Identity()) * mesh.coord.row(n).transpose();
  return uvw;
}

// a GIMP point (lp0 = (0.1, 0.1), vp0 = 0.04) whose domain straddles a grid node
MaterialPoint gimpPoint() {
  MaterialPoint mp;
  mp.mpType = MpType::GIMP;
  mp.mpC = mp.X0 = Vector2d(1.95, 2.03);
  mp.lp0 = mp.lp = Vector2d(0.1, 0.1);
  mp.vp0 = mp.vp = 0.04;
  return mp;
}

struct Errors {
  double area, length;  // |4 lx ly - det F V0|, max_i |l_i - l0_i F_ii| (0 if not checked)
};
Errors domainErrors(DomainUpdate method, const Mode& m) {
  Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);
  std::vector<MaterialPoint> mpData{gimpPoint()};
  elemMPinfo(mesh, mpData);  // nIN, nn for the corner method
  MaterialPoint& mp = mpData[0];
  mp.F = F3(m.F);
  mp.Fn = Matrix3d::Identity();
  updateDomain(mesh, homogeneousUvw(mesh, m.F), method, mp);
  Errors e{std::abs(4 * mp.lp(0) * mp.lp(1) - m.F.determinant() * mp.vp0), 0.0};
  if (m.checkLengths)
    e.length = (mp.lp - mp.lp0.cwiseProduct(m.F.diagonal())).cwiseAbs().maxCoeff();
  return e;
}

// half lengths after one update by method from l0 = (0.1, 0.05) under x = F X (Fn = I)
Vector2d handLengths(DomainUpdate method, const Eigen::Matrix2d& F) {
  Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);
  std::vector<MaterialPoint> mpData{gimpPoint()};
  mpData[0].lp0 = mpData[0].lp = Vector2d(0.1, 0.05);
  mpData[0].vp0 = mpData[0].vp = 0.02;
  elemMPinfo(mesh, mpData);  // nIN, nn for the corner method
  MaterialPoint& mp = mpData[0];
  mp.F = F3(F);
  mp.Fn = Matrix3d::Identity();
  updateDomain(mesh, homogeneousUvw(mesh, F), method, mp);
  return mp.lp;
}

// check one row of table 2: expected[k] = true for a tick, false for a cross
void checkRow(DomainUpdate method, const bool expected[4]) {
  const std::vector<Mode> ms = modes();
  for (int k = 0; k < 4; ++k) {
    CAPTURE(ms[k].name);
    const Errors e = domainErrors(method, ms[k]);
    CAPTURE(e.area);
    CAPTURE(e.length);
    if (expected[k]) {
      CHECK(e.area <= tolOK);
      CHECK(e.length <= tolOK);
    } else {
      CHECK(std::max(e.area, e.length) > tolBad);
    }
  }
}
}  // namespace

TEST_SUITE("updateDomain") {
  //                         stretch hydro  shear  rotation
  TEST_CASE("updateDomain: no update (None) - stretch x / hydrostatic x / shear ok / rotation ok") {
    const bool row[4] = {false, false, true, true};
    checkRow(DomainUpdate::None, row);
  }
  TEST_CASE("updateDomain: det(F) update (eq 32) - stretch x (lengths) / others ok") {
    const bool row[4] = {false, true, true, true};
    checkRow(DomainUpdate::DetF, row);
    // the cross is the artificial orthogonal contraction: area right, lengths wrong
    const Errors e = domainErrors(DomainUpdate::DetF, modes()[0]);
    CHECK(e.area <= tolOK);
    CHECK(e.length > tolBad);
  }
  TEST_CASE("updateDomain: F_ii update (eq 33) - rotation x (vanishing domain) / others ok") {
    const bool row[4] = {true, true, true, false};
    checkRow(DomainUpdate::Fii, row);
    // l = l0 cos(60) in both directions: the domain shrinks to a quarter
    Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);
    MaterialPoint mp = gimpPoint();
    mp.F = F3(modes()[3].F);
    updateDomain(mesh, Eigen::VectorXd::Zero(mesh.nDoF()), DomainUpdate::Fii, mp);
    CHECK((mp.lp - 0.5 * mp.lp0).norm() <= tolOK);
  }
  TEST_CASE("updateDomain: U_ii update (eq 34) - shear x (volume changes) / others ok") {
    const bool row[4] = {true, true, false, true};
    checkRow(DomainUpdate::Uii, row);
    // U of simple shear with gamma = 1 is [2 1; 1 3]/sqrt(5): area grows by 6/5
    Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);
    MaterialPoint mp = gimpPoint();
    mp.F = F3(modes()[2].F);
    updateDomain(mesh, Eigen::VectorXd::Zero(mesh.nDoF()), DomainUpdate::Uii, mp);
    CHECK((mp.lp - mp.lp0.cwiseProduct(Vector2d(2, 3)) / std::sqrt(5.0)).norm() <= tolOK);
  }
  TEST_CASE("updateDomain: corner update (eqs 35-37) - all four modes ok / stretch lengths ok") {
    const bool row[4] = {true, true, true, true};
    checkRow(DomainUpdate::Corner, row);
  }
  TEST_CASE("updateDomain: F_ii with volume correction (eq 38) - all four modes ok") {
    const bool row[4] = {true, true, true, true};
    checkRow(DomainUpdate::FiiVol, row);
  }
  TEST_CASE("updateDomain: incremental F_ii with volume correction (eq 39) - Fn = I equals eq 38") {
    const bool row[4] = {true, true, true, true};
    checkRow(DomainUpdate::FiiVolInc, row);
  }
  TEST_CASE("updateDomain: incremental eq 39 over two steps uses dF = F Fn^-1 and the current lengths") {
    Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);
    MaterialPoint mp = gimpPoint();
    Eigen::Matrix2d F1, F2;
    F1 << 1.1, 0, 0, 0.9;
    F2 << 1.0, 0.2, 0, 1.3;  // shear and stretch in the second step
    mp.lp = Vector2d(0.11, 0.09);  // lengths after step 1 (= l0 F1_ii)
    mp.Fn = F3(F1);
    mp.F = F3(F2 * F1);
    updateDomain(mesh, Eigen::VectorXd::Zero(mesh.nDoF()), DomainUpdate::FiiVolInc, mp);
    // dF = F2: |dF_ii| = (1, 1.3), det dF = 1.3, no volume correction needed
    CHECK((mp.lp - Vector2d(0.11, 0.09 * 1.3)).norm() <= tolOK);
    CHECK(std::abs(4 * mp.lp.prod() - (F2 * F1).determinant() * mp.vp0) <= tolOK);
  }

  // Hand calculations of every GIMP update: l0 = (0.1, 0.05), homogeneous fields.
  // The expected half lengths are written out from the equations of [Lagrangian] sec 6.4;
  // nothing below calls the library to make them (no stretchTensor, no det).
  TEST_CASE("updateDomain: hand calculation - pure stretch F = diag(1.2 0.9) for every method") {
    Eigen::Matrix2d F;
    F << 1.2, 0, 0, 0.9;
    const double r = std::sqrt(1.08);  // det F = 1.2 * 0.9
    CHECK((handLengths(DomainUpdate::None, F) - Vector2d(0.1, 0.05)).norm() <= tolOK);
    CHECK((handLengths(DomainUpdate::DetF, F) - Vector2d(0.1 * r, 0.05 * r)).norm() <= tolOK);  // eq 32
    // U = F for a stretch: Fii, Uii, the corner update (midpoints at 1.2 lx, 0.9 ly, no
    // volume correction since 1.2 * 0.9 = det F) and both volume-corrected forms agree
    for (DomainUpdate m : {DomainUpdate::Fii, DomainUpdate::Uii, DomainUpdate::Corner, DomainUpdate::FiiVol,
                           DomainUpdate::FiiVolInc}) {
      CAPTURE(int(m));
      CHECK((handLengths(m, F) - Vector2d(0.12, 0.045)).norm() <= tolOK);
    }
  }
  TEST_CASE("updateDomain: hand calculation - rotation by 30 deg for every method") {
    const double c = std::sqrt(3.0) / 2.0, s = 0.5;  // cos 30, sin 30
    Eigen::Matrix2d F;
    F << c, -s, s, c;
    for (DomainUpdate m : {DomainUpdate::None, DomainUpdate::DetF, DomainUpdate::Uii, DomainUpdate::FiiVol,
                           DomainUpdate::FiiVolInc}) {
      CAPTURE(int(m));  // det F = 1, U = I, eq 38: l0 c (1 / c^2)^(1/2) = l0
      CHECK((handLengths(m, F) - Vector2d(0.1, 0.05)).norm() <= tolOK);
    }
    CHECK((handLengths(DomainUpdate::Fii, F) - Vector2d(0.1 * c, 0.05 * c)).norm() <= tolOK);  // eq 33
    // eqs 35-37: edge midpoints (0, -ly), (lx, 0), (0, ly), (-lx, 0) rotate to
    // (s ly, -c ly), (c lx, s lx), ...: half extents max(s ly, c lx) = c lx = 0.0866 and
    // max(c ly, s lx) = s lx = 0.05; scaled by (lx ly / (c lx s lx))^(1/2) to the area
    const double k = std::sqrt(0.1 * 0.05 / (c * 0.1 * s * 0.1));
    CHECK((handLengths(DomainUpdate::Corner, F) - Vector2d(c * 0.1 * k, s * 0.1 * k)).norm() <= tolOK);
  }
  TEST_CASE("updateDomain: hand calculation - simple shear gamma = 3 for every method") {
    Eigen::Matrix2d F;
    F << 1, 3, 0, 1;
    for (DomainUpdate m : {DomainUpdate::None, DomainUpdate::DetF, DomainUpdate::Fii, DomainUpdate::FiiVol,
                           DomainUpdate::FiiVolInc}) {
      CAPTURE(int(m));  // F11 = F22 = det F = 1
      CHECK((handLengths(m, F) - Vector2d(0.1, 0.05)).norm() <= tolOK);
    }
    // eq 34: C = F'F = [1 3; 3 10], det C = 1, tr C = 11, so U = (C + I) / sqrt(11 + 2)
    CHECK((handLengths(DomainUpdate::Uii, F) - Vector2d(0.1 * 2, 0.05 * 11) / std::sqrt(13.0)).norm() <= tolOK);
    // eqs 35-37: midpoints (0, -ly) -> (-3 ly, -ly), (lx, 0) -> (lx, 0), ...: half extents
    // max(lx, 3 ly) = 0.15 and ly = 0.05, scaled by (lx ly / (0.15 ly))^(1/2) = (2/3)^(1/2)
    const double k = std::sqrt(2.0 / 3.0);
    CHECK((handLengths(DomainUpdate::Corner, F) - Vector2d(0.15 * k, 0.05 * k)).norm() <= tolOK);
  }

  TEST_CASE("updateDomain: standard MPM points keep no domain") {
    Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);
    MaterialPoint mp;
    mp.mpType = MpType::MPM;
    mp.mpC = Vector2d(1.5, 1.5);
    mp.F = F3(modes()[0].F);
    updateDomain(mesh, Eigen::VectorXd::Zero(mesh.nDoF()), DomainUpdate::Uii, mp);
    CHECK(mp.lp.norm() == 0.0);
    updateGIMPDomain(mesh, Eigen::VectorXd::Zero(mesh.nDoF()), mp);  // the core's eq 34 too
    CHECK(mp.lp.norm() == 0.0);
  }

  TEST_CASE("updateDomain: CPDI1 s = F s0 / t = F t0 / area = det F area0 / lp = half bounding box") {
    Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);
    MaterialPoint mp;
    mp.mpType = MpType::CPDI1;
    mp.cpdi = CpdiDomain();
    mp.mpC = Vector2d(2.1, 1.7);
    mp.cpdi->st0 << 0.5, -0.2, 0.1, 0.4;
    mp.cpdi->st = mp.cpdi->st0;
    const double A0 = std::abs(mp.cpdi->st0.determinant());
    for (const Mode& m : modes()) {
      CAPTURE(m.name);
      Eigen::Matrix2d F = m.F;
      F(1, 0) += 0.05;  // a general F on top of the mode
      mp.F = F3(F);
      updateDomain(mesh, Eigen::VectorXd::Zero(mesh.nDoF()), DomainUpdate::Uii, mp);
      CHECK((mp.cpdi->st - F * mp.cpdi->st0).norm() <= tolOK);
      const Vector2d s = mp.cpdi->st.col(0), t = mp.cpdi->st.col(1);
      CHECK(std::abs(std::abs(s(0) * t(1) - s(1) * t(0)) - F.determinant() * A0) <= tolOK);
      const Vector2d half = 0.5 * (s.cwiseAbs() + t.cwiseAbs());
      CHECK((mp.lp - half).norm() <= tolOK);
    }
  }

  TEST_CASE("updateDomain: CPDI2 corners move to F x_c under a homogeneous field / vp = det F vp0") {
    for (const Mode& m : modes()) {
      CAPTURE(m.name);
      Mesh mesh = formCoord2D(6, 6, 6.0, 6.0);
      std::vector<MaterialPoint> mpData(1);
      MaterialPoint& mp = mpData[0];
      mp.mpType = MpType::CPDI2;
      mp.cpdi = CpdiDomain();
      mp.cpdi->xc << 2.30, 3.55, 3.40, 2.15,  // distorted quadrilateral, anticlockwise
          2.00, 1.85, 3.10, 2.75;
      mp.mpC = mp.cpdi->xc.rowwise().mean();
      const Corners x0 = mp.cpdi->xc;
      double A0 = 0;  // shoelace, written out here
      for (int c = 0; c < 4; ++c)
        A0 += 0.5 * (x0(0, c) * x0(1, (c + 1) % 4) - x0(0, (c + 1) % 4) * x0(1, c));
      mp.vp0 = mp.vp = A0;
      elemMPinfoCPDI(mesh, mpData);
      mp.F = F3(m.F);
      updateDomain(mesh, homogeneousUvw(mesh, m.F), DomainUpdate::Uii, mp);
      CHECK((mp.cpdi->xc - m.F * x0).norm() <= tolOK);
      CHECK(std::abs(mp.vp - m.F.determinant() * A0) <= tolOK);
      const Vector2d half = 0.5 * (mp.cpdi->xc.rowwise().maxCoeff() - mp.cpdi->xc.rowwise().minCoeff());
      CHECK((mp.lp - half).norm() <= tolOK);
    }
  }

  TEST_CASE("updateDomain: corner method inside updateMPs moves the start-of-step corners") {
    // eq 35: the corners X~ +- l at the START of the step are moved by the grid
    // displacement. updateMPs first moves mp.mpC, so the corners must not be
    // taken about the updated position. A non-homogeneous (quadratic) field
    // makes the difference visible.
    Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);
    std::vector<MaterialPoint> mpData{gimpPoint()};
    mpData[0].mpC = mpData[0].X0 = Vector2d(1.5, 1.5);  // domain inside one cell
    elemMPinfo(mesh, mpData);
    Eigen::VectorXd uvw(mesh.nDoF());
    for (int n = 0; n < mesh.nodes(); ++n) {
      const double X = mesh.coord(n, 0), Y = mesh.coord(n, 1);
      uvw.segment<2>(dof(n, 0)) = Vector2d(0.1 * X * Y, 0.05 * X * Y);  // bilinear in each cell
    }
    // F at the point: the gradient of the bilinear interpolant at the centre
    MaterialPoint& mp = mpData[0];
    const Vector2d Xp = mp.mpC;
    Eigen::Matrix2d F;
    F << 1 + 0.1 * Xp(1), 0.1 * Xp(0), 0.05 * Xp(1), 1 + 0.05 * Xp(0);
    mp.F = F3(F);
    // expected: corners X~_c moved by u(X~_c) = (0.1, 0.05) X Y (exact in the cell)
    Corners x;
    const double a[4] = {-1, 1, 1, -1}, b[4] = {-1, -1, 1, 1};
    for (int c = 0; c < 4; ++c) {
      const Vector2d Xc = Xp + Vector2d(a[c] * mp.lp(0), b[c] * mp.lp(1));
      x.col(c) = Xc + Vector2d(0.1, 0.05) * Xc(0) * Xc(1);
    }
    Corners m;
    for (int c = 0; c < 4; ++c) m.col(c) = 0.5 * (x.col(c) + x.col((c + 1) % 4));
    const Vector2d lm = 0.5 * (m.rowwise().maxCoeff() - m.rowwise().minCoeff());
    const Vector2d lExpected = lm * std::sqrt(F.determinant() * mp.lp0.prod() / lm.prod());

    MaterialPoint direct = mp;  // updateDomain called with the start-of-step position
    updateDomain(mesh, uvw, DomainUpdate::Corner, direct);
    CHECK((direct.lp - lExpected).norm() <= tolOK);

    struct Corner : UpdateDomain {                              // the program's hook
      void updateDomain(const Mesh& g, const Eigen::VectorXd& u, MaterialPoint& p) const override {
        ample::updateDomain(g, u, DomainUpdate::Corner, p);
      }
    };
    updateMPs(mesh, uvw, mpData, Corner());
    CHECK((mpData[0].lp - lExpected).norm() <= tolOK);
  }
}
