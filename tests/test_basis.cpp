// Tests of the basis functions: SvpMPM, SvpGIMP (seed 002 eqs 23-26), MPMbasis
// (eq 22) and elemMPinfo: partition of unity, gradients against finite
// differences, continuity across the GIMP regions, GIMP = MPM inside a cell.
#include "ample/MPMbasis.h"
#include "ample/SvpGIMP.h"
#include "ample/SvpMPM.h"
#include "testProblems.h"
#include <doctest/doctest.h>
#include <cmath>

using namespace ample;

namespace {
const double h = 0.5, lp = 0.1;  // grid spacing and domain half length (lp <= h/2)
// sum over the nodes of a 1D grid (nodes at k h) of S and dS at position x
Basis1D sum1D(double x, bool gimp) {
  Basis1D s{0, 0};
  for (int k = -4; k <= 12; ++k) {
    const Basis1D b = gimp ? SvpGIMP(x - k * h, h, lp) : SvpMPM(x - k * h, h);
    s.S += b.S;
    s.dS += b.dS;
  }
  return s;
}
}  // namespace

TEST_SUITE("SvpMPM") {
  TEST_CASE("SvpMPM: partition of unity, zero gradient sum, linear reproduction") {
    for (double x = 0.013; x < 4.0; x += 0.0371) {
      const Basis1D s = sum1D(x, false);
      CHECK(std::abs(s.S - 1.0) <= 1e-14);
      CHECK(std::abs(s.dS) <= 1e-12);
      double xr = 0;
      for (int k = -4; k <= 12; ++k) xr += SvpMPM(x - k * h, h).S * k * h;
      CHECK(std::abs(xr - x) <= 1e-13);
    }
  }
  TEST_CASE("SvpMPM: values of eq 23 and gradients of eq 24") {
    CHECK(SvpMPM(0.0, h).S == 1.0);
    CHECK(SvpMPM(-0.2, h).S == doctest::Approx(0.6).epsilon(1e-14));
    CHECK(SvpMPM(0.2, h).dS == doctest::Approx(-2.0).epsilon(1e-14));
    CHECK(SvpMPM(0.6, h).S == 0.0);
  }
}

TEST_SUITE("SvpGIMP") {
  TEST_CASE("SvpGIMP: partition of unity and zero gradient sum for lp <= h/2") {
    for (double x = 0.013; x < 4.0; x += 0.0371) {
      const Basis1D s = sum1D(x, true);
      CHECK(std::abs(s.S - 1.0) <= 1e-14);
      CHECK(std::abs(s.dS) <= 1e-12);
    }
  }
  TEST_CASE("SvpGIMP: gradient equals central differences in each region A-E") {
    for (double d : {-0.55, -0.45, -0.3, -0.05, 0.07, 0.3, 0.45, 0.55}) {  // A A B C C D E E
      CAPTURE(d);
      const double e = 1e-6;
      const double fd = (SvpGIMP(d + e, h, lp).S - SvpGIMP(d - e, h, lp).S) / (2 * e);
      CHECK(std::abs(SvpGIMP(d, h, lp).dS - fd) <= 1e-7);
    }
  }
  TEST_CASE("SvpGIMP: value and gradient continuous across the region boundaries") {
    for (double b : {-h - lp, -h + lp, -lp, lp, h - lp, h + lp}) {
      CAPTURE(b);
      const Basis1D lo = SvpGIMP(b - 1e-10, h, lp), hi = SvpGIMP(b + 1e-10, h, lp);
      CHECK(std::abs(lo.S - hi.S) <= 1e-8);
      CHECK(std::abs(lo.dS - hi.dS) <= 1e-7);
    }
  }
  TEST_CASE("SvpGIMP: equals standard MPM when the domain lies inside one cell") {
    for (double d : {-0.35, -0.2, -0.12, 0.12, 0.25, 0.38}) {  // regions B and D
      CHECK(SvpGIMP(d, h, lp).S == doctest::Approx(SvpMPM(d, h).S).epsilon(1e-14));
      CHECK(SvpGIMP(d, h, lp).dS == doctest::Approx(SvpMPM(d, h).dS).epsilon(1e-14));
    }
    CHECK(SvpGIMP(0.2, h, 0.0).S == SvpMPM(0.2, h).S);  // lp = 0 is standard MPM
  }
  TEST_CASE("SvpGIMP: the convolution of eq 20 at a point in region C") {
    // S = (1/2lp) int_{d-lp}^{d+lp} (1 - |s|/h) ds for |d| < lp
    const double d = 0.04, a = d - lp, b = d + lp;
    const double exact = (b - a - (a * a + b * b) / (2 * h)) / (2 * lp);
    CHECK(SvpGIMP(d, h, lp).S == doctest::Approx(exact).epsilon(1e-14));
  }
}

TEST_SUITE("MPMbasis") {
  TEST_CASE("MPMbasis: 2D partition of unity and linear reproduction, MPM and GIMP") {
    for (MpType t : {MpType::MPM, MpType::GIMP}) {
      Analysis an = testing::smallBlock(t, CmType::Elastic, 3);
      for (MaterialPoint& mp : an.mpData) mp.mpC += Vector2d(0.13, -0.07);  // off the cell centres
      elemMPinfo(an.mesh, an.mpData);
      for (const MaterialPoint& mp : an.mpData) {
        double S = 0;
        Vector2d x = Vector2d::Zero(), dS = Vector2d::Zero();
        Eigen::Matrix2d gradX = Eigen::Matrix2d::Zero();  // sum_v X_v (x) dS_v = I
        for (int v = 0; v < mp.nn; ++v) {
          const Vector2d Xv = an.mesh.coord.row(mp.nIN[v]).transpose();
          S += mp.Svp[v];
          x += mp.Svp[v] * Xv;
          dS += mp.dSvp.col(v);
          gradX += Xv * mp.dSvp.col(v).transpose();
        }
        CHECK(std::abs(S - 1.0) <= 1e-14);
        CHECK((x - mp.mpC).norm() <= 1e-13);
        CHECK(dS.norm() <= 1e-12);
        CHECK((gradX - Eigen::Matrix2d::Identity()).norm() <= 1e-12);
      }
    }
  }
  TEST_CASE("MPMbasis: 2D gradient equals central differences of the basis") {
    Analysis an = testing::smallBlock(MpType::GIMP, CmType::Elastic, 2);
    MaterialPoint mp = an.mpData[0];
    mp.mpC = Vector2d(1.93, 2.08);  // domain straddles a cell corner
    elemMPinfo(an.mesh, an.mpData);
    std::vector<MaterialPoint> one{mp};
    elemMPinfo(an.mesh, one);
    for (int i = 0; i < nD; ++i) {
      MaterialPoint p = one[0], m = one[0];
      p.mpC(i) += 1e-6;
      m.mpC(i) -= 1e-6;
      MPMbasis(an.mesh, p);
      MPMbasis(an.mesh, m);
      for (int v = 0; v < one[0].nn; ++v)
        CHECK(std::abs((p.Svp[v] - m.Svp[v]) / 2e-6 - one[0].dSvp(i, v)) <= 1e-7);
    }
  }
}
