// Tests of detMPsFbar (locking=Fbar, ample/locking/): its tangent against central differences
// of its own internal force (UL, PC, SS; MPM, GIMP, CPDI2; elastic near nu = 0.5 and von Mises
// on the yield surface), the patch test (a homogeneous increment gives Fbar = F and detMPs'
// forces and stresses), the vanishing of the remedy with one point per cell (detMPs' fint and
// Kt), and the cell average itself, computed by hand.
#include "ample/locking/detMPsFbar.h"
#include "testProblems.h"
#include <doctest/doctest.h>
#include <cmath>

using namespace ample;

namespace {

DetMPsOut fbar(const Analysis& an, const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData,
               Formulation form) {
  DetMPsOut out;
  detMPsFbar(an.mesh, uvw, mpData, form, out);
  return out;
}

// |Kt - Kfd| / |Kt|, Kfd by central differences of detMPsFbar's fint (step 1e-7)
double fbarTangentError(Analysis& an, const Eigen::VectorXd& uvw, Formulation form) {
  const Eigen::MatrixXd Kt = Eigen::MatrixXd(fbar(an, uvw, an.mpData, form).Kt);
  Eigen::MatrixXd Kfd = Eigen::MatrixXd::Zero(Kt.rows(), Kt.cols());
  const double d = 1e-7;
  for (int c = 0; c < uvw.size(); ++c) {
    if (Kt.col(c).norm() == 0.0) continue;
    Eigen::VectorXd up = uvw, um = uvw;
    up(c) += d;
    um(c) -= d;
    Kfd.col(c) = (fbar(an, up, an.mpData, form).fint - fbar(an, um, an.mpData, form).fint) / (2 * d);
  }
  return (Kt - Kfd).norm() / Kt.norm();
}

// the points' Kirchhoff stress lies on the von Mises surface rho = sqrt(2 J2) = rho_y
bool allYielding(const std::vector<MaterialPoint>& mpData) {
  for (const MaterialPoint& mp : mpData) {
    const Vector6d tau = mp.sig * mp.F.determinant();
    const double p = tau.head<3>().sum() / 3.0;
    const double rho = std::sqrt((tau.head<3>().array() - p).square().sum() + 2.0 * tau.tail<3>().squaredNorm());
    if (std::abs(rho - mp.mCst.rhoY) > 1e-9 * mp.mCst.rhoY) return false;
  }
  return true;
}

double relDiff(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).norm() / b.norm(); }

}  // namespace

TEST_SUITE("detMPsFbar") {
  TEST_CASE("detMPsFbar: tangent equals central differences of its fint (UL, PC, SS; MPM, GIMP, CPDI2; elastic nu = 0.49, von Mises)") {
    for (MpType t : {MpType::MPM, MpType::GIMP, MpType::CPDI2})
      for (CmType c : {CmType::Elastic, CmType::VonMises})
        for (Formulation form : {Formulation::UL, Formulation::PC, Formulation::SS}) {
          CAPTURE(int(t));
          CAPTURE(int(c));
          CAPTURE(int(form));
          Analysis an = testing::smallBlock(t, c);
          for (MaterialPoint& mp : an.mpData) mp.mCst.nu = 0.49;
          testing::prestrain(an.mpData, 7);
          for (MaterialPoint& mp : an.mpData) mp.mpC += Vector2d(0.13, -0.07);  // domains straddle edges
          elemMPinfo(an.mesh, an.mpData);
          const Eigen::VectorXd uvw = testing::randomUvw(an, 0.02, 11);
          if (c == CmType::VonMises) {                     // a smooth FD needs every point yielding
            fbar(an, uvw, an.mpData, form);
            REQUIRE(allYielding(an.mpData));
          }
          CHECK(fbarTangentError(an, uvw, form) < 1e-6);
        }
  }

  TEST_CASE("detMPsFbar: a homogeneous increment gives Fbar = F: detMPs' fint and stresses within 1e-12 (patch test)") {
    for (MpType t : {MpType::MPM, MpType::GIMP})
      for (Formulation form : {Formulation::UL, Formulation::PC, Formulation::SS}) {
        CAPTURE(int(t));
        CAPTURE(int(form));
        Analysis an = testing::smallBlock(t, CmType::VonMises);
        testing::prestrain(an.mpData, 3);                  // each point its own state: stresses differ
        elemMPinfo(an.mesh, an.mpData);
        Eigen::Matrix2d Hh;                                // du = Hh X at every node
        Hh << 0.031, -0.012, 0.007, -0.024;
        Eigen::VectorXd uvw(an.mesh.nDoF());
        for (int n = 0; n < an.mesh.nodes(); ++n)
          uvw.segment<2>(2 * n) = Hh * an.mesh.coord.row(n).transpose();
        std::vector<MaterialPoint> plain = an.mpData, barred = an.mpData;
        const Eigen::VectorXd f0 = detMPsOf(uvw, plain, form).fint;
        const Eigen::VectorXd f1 = fbar(an, uvw, barred, form).fint;
        CHECK(relDiff(f1, f0) < 1e-12);
        double dsig = 0, sigMax = 0, dF = 0;
        for (size_t p = 0; p < plain.size(); ++p) {
          dsig = std::max(dsig, (barred[p].sig - plain[p].sig).cwiseAbs().maxCoeff());
          sigMax = std::max(sigMax, plain[p].sig.cwiseAbs().maxCoeff());
          dF = std::max(dF, (barred[p].F - plain[p].F).cwiseAbs().maxCoeff());
        }
        CHECK(dsig < 1e-12 * sigMax);
        CHECK(dF < 1e-14);
      }
  }

  TEST_CASE("detMPsFbar: with one point per cell the remedy vanishes: detMPs' fint and Kt within 1e-12") {
    for (MpType t : {MpType::MPM, MpType::GIMP})
      for (Formulation form : {Formulation::UL, Formulation::SS}) {
        CAPTURE(int(t));
        CAPTURE(int(form));
        Analysis an = testing::smallBlock(t, CmType::Elastic, 1);
        testing::prestrain(an.mpData, 5);
        elemMPinfo(an.mesh, an.mpData);
        const Eigen::VectorXd uvw = testing::randomUvw(an, 0.02, 13);
        std::vector<MaterialPoint> plain = an.mpData, barred = an.mpData;
        const DetMPsOut a = detMPsOf(uvw, plain, form), b = fbar(an, uvw, barred, form);
        CHECK(relDiff(b.fint, a.fint) < 1e-12);
        CHECK(relDiff(Eigen::MatrixXd(b.Kt), Eigen::MatrixXd(a.Kt)) < 1e-12);
      }
  }

  TEST_CASE("detMPsFbar: every point of a cell takes the cell's volume change (dJbar = sum dJ v^n / sum v^n, by hand)") {
    Analysis an = testing::smallBlock(MpType::MPM, CmType::Elastic);   // 2 x 2 points in 4 cells
    elemMPinfo(an.mesh, an.mpData);
    Eigen::VectorXd uvw = Eigen::VectorXd::Zero(an.mesh.nDoF());
    uvw(2 * 6) = 0.1;                                      // node 6 = (1, 1) moves 0.1 m in x
    std::vector<MaterialPoint> pts = an.mpData;
    fbar(an, uvw, pts, Formulation::UL);
    // cell 5 = [1, 2] x [1, 2]: u_x = 0.1 (2 - x)(2 - y), so dJ = 1 + du_x/dx = 1 - 0.1 (2 - y):
    // 0.925 and 0.975 at the rows y = 1.25, 1.75; with equal volumes the cell's average is 0.95
    for (size_t p = 0; p < pts.size(); ++p)
      if (cellHolding(an.mesh, pts[p].mpC) == 5) CHECK(pts[p].F.determinant() == doctest::Approx(0.95).epsilon(1e-14));
  }
}
