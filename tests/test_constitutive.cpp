// Tests of the constitutive models: Hooke3d ([AMPLE] eq 5) and VMconst
// (eq 11, backward-Euler radial return and its algorithmic tangent).
// Voigt order [xx yy zz xy yz zx], strains with engineering shear.
#include "constitutive/Hooke3d.h"
#include "constitutive/VMconst.h"
#include <doctest/doctest.h>
#include <cmath>

using namespace ample;

namespace {
const Vector3d mCst(1e6, 0.3, 2e4);  // E, nu, rho_y
const double E = mCst(0), nu = mCst(1), rhoY = mCst(2);
const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), G = E / (2 * (1 + nu));
const double K = lam + 2 * G / 3;  // bulk modulus

Vector6d m1() {  // [1 1 1 0 0 0]
  Vector6d m;
  m << 1, 1, 1, 0, 0, 0;
  return m;
}
double meanOf(const Vector6d& s) { return s.head<3>().sum() / 3.0; }
Vector6d devOf(const Vector6d& s) { return s - meanOf(s) * m1(); }
double rhoOf(const Vector6d& s) {  // sqrt(2 J2) = |s| of the stress 6-vector
  const Vector6d d = devOf(s);
  return std::sqrt(d.head<3>().squaredNorm() + 2 * d.tail<3>().squaredNorm());
}
// the elastic matrix for E = 1e6 Pa, nu = 0.3 written out by hand: lambda = E nu / ((1 + nu)
// (1 - 2 nu)) = 3e5 / 0.52 = 576923.0769230769, G = E / (2 (1 + nu)) = 1e6 / 2.6 =
// 384615.3846153846, lambda + 2 G = 1346153.846153846; G on the engineering shears
Matrix6d handD() {
  const double l = 576923.0769230769, g = 384615.3846153846, d = 1346153.846153846;
  Matrix6d D;
  D << d, l, l, 0, 0, 0,
       l, d, l, 0, 0, 0,
       l, l, d, 0, 0, 0,
       0, 0, 0, g, 0, 0,
       0, 0, 0, 0, g, 0,
       0, 0, 0, 0, 0, g;
  return D;
}
// a plastic trial strain with all six components non-zero
Vector6d plasticStrain() {
  Vector6d eps;
  eps << 0.09, -0.06, 0.03, 0.045, -0.03, 0.06;
  return eps;
}
// its return factor theta = rho_y / rho_tr by hand: mean strain 0.02, deviator (tensor
// shears = half the engineering ones) [0.07 -0.08 0.01 | 0.0225 -0.015 0.03], |e|^2 =
// 0.0114 + 2 * 0.00163125 = 0.0146625, rho_tr = 2G |e| = 93145.23875624873 Pa
const double rhoTrial = 93145.23875624873, thetaHand = rhoY / rhoTrial;
}  // namespace

TEST_SUITE("Hooke3d") {
  TEST_CASE("Hooke3d: uniaxial strain gives lambda + 2G and lambda") {
    Vector6d eps = Vector6d::Zero();
    eps(1) = 1e-3;
    const ConstOut o = Hooke3d(eps, mCst);
    CHECK(o.Ksig(1) == doctest::Approx((lam + 2 * G) * 1e-3).epsilon(1e-14));
    CHECK(o.Ksig(0) == doctest::Approx(lam * 1e-3).epsilon(1e-14));
    CHECK(o.Ksig(2) == doctest::Approx(lam * 1e-3).epsilon(1e-14));
    CHECK(o.Ksig.tail<3>().norm() == 0.0);
    CHECK(o.epsE == eps);  // elastic: the trial strain is the elastic strain
  }
  TEST_CASE("Hooke3d: pure (engineering) shear gives tau = G gamma") {
    for (int c = 3; c < 6; ++c) {
      Vector6d eps = Vector6d::Zero();
      eps(c) = 2e-3;  // gamma
      const ConstOut o = Hooke3d(eps, mCst);
      CHECK(o.Ksig(c) == doctest::Approx(G * 2e-3).epsilon(1e-14));
      CHECK(o.Ksig.norm() == doctest::Approx(G * 2e-3).epsilon(1e-14));  // nothing else
    }
  }
  TEST_CASE("Hooke3d: volumetric strain gives p = 3K e / D symmetric") {
    const ConstOut o = Hooke3d(1e-3 * m1(), mCst);
    CHECK(meanOf(o.Ksig) == doctest::Approx(3 * K * 1e-3).epsilon(1e-13));
    CHECK(rhoOf(o.Ksig) <= 1e-12 * std::abs(meanOf(o.Ksig)));
    CHECK((o.D - o.D.transpose()).norm() == 0.0);
    CHECK((o.D - handD()).norm() <= 1e-12 * handD().norm());
  }
}

TEST_SUITE("VMconst") {
  TEST_CASE("VMconst: inside the surface the trial state stands with the elastic tangent") {
    Vector6d eps;
    eps << 1e-3, -2e-3, 5e-4, 1e-3, -4e-4, 7e-4;
    const ConstOut o = VMconst(eps, mCst), e = Hooke3d(eps, mCst);
    REQUIRE(rhoOf(e.Ksig) < rhoY);
    CHECK((o.Ksig - e.D * eps).norm() <= 1e-14 * e.Ksig.norm());
    CHECK((o.D - handD()).norm() <= 1e-12 * handD().norm());
    CHECK(o.epsE == eps);
    // just outside (rho_tr = 1.01 rho_y) the trial state does not stand: it is returned
    const ConstOut out = VMconst(plasticStrain() * (1.01 * rhoY / rhoTrial), mCst);
    CHECK(std::abs(rhoOf(out.Ksig) - rhoY) <= 1e-10 * rhoY);
  }
  TEST_CASE("VMconst: a trial state far outside returns onto the surface radially") {
    const Vector6d eps = plasticStrain();
    const ConstOut o = VMconst(eps, mCst), e = Hooke3d(eps, mCst);
    REQUIRE(rhoOf(e.Ksig) > 4 * rhoY);  // well outside the surface
    CHECK(std::abs(rhoOf(o.Ksig) - rhoY) <= 1e-10 * rhoY);
    CHECK(meanOf(o.Ksig) == doctest::Approx(meanOf(e.Ksig)).epsilon(1e-13));  // p unchanged
    const Vector6d sT = devOf(e.Ksig), s = devOf(o.Ksig);  // same deviatoric direction
    CHECK((s / s.norm() - sT / sT.norm()).norm() <= 1e-13);
  }
  TEST_CASE("VMconst: the returned elastic strain gives the returned stress / D epsE = tau / theta by hand") {
    const Vector6d eps = plasticStrain();
    const ConstOut o = VMconst(eps, mCst);
    CHECK((handD() * o.epsE - o.Ksig).norm() <= 1e-10 * o.Ksig.norm());
    // the volumetric strain is kept, the deviatoric one scaled by theta = rho_y / rho_tr
    const Vector6d eVol = 0.02 * m1();
    CHECK((o.epsE - (eVol + thetaHand * (eps - eVol))).norm() <= 1e-12 * eps.norm());
    CHECK(std::abs(rhoOf(o.Ksig) - thetaHand * rhoTrial) <= 1e-10 * rhoY);
  }
  TEST_CASE("VMconst: algorithmic tangent equals central differences of the return map") {
    const Vector6d eps = plasticStrain();
    const Matrix6d D = VMconst(eps, mCst).D;
    Matrix6d Dfd;
    const double d = 1e-7;
    for (int c = 0; c < 6; ++c) {
      Vector6d ep = eps, em = eps;
      ep(c) += d;
      em(c) -= d;
      Dfd.col(c) = (VMconst(ep, mCst).Ksig - VMconst(em, mCst).Ksig) / (2 * d);
    }
    CHECK((D - Dfd).norm() <= 1e-6 * D.norm());
    CHECK((D - D.transpose()).norm() <= 1e-12 * D.norm());  // associated flow: symmetric
    // a strain increment along the trial deviator changes no deviatoric stress (the return
    // is radial): the deviatoric part of Dfd u is zero, where the elastic one is 2G u
    Vector6d u = devOf(eps);
    u /= u.norm();
    CHECK(rhoOf(Dfd * u) <= 1e-6 * 2 * G);
    CHECK(std::abs(meanOf(Dfd * u)) <= 1e-6 * K);  // u has no volume change
    // while a volumetric strain gets the elastic bulk response: D m = 3K m
    CHECK((D * m1() - 3 * K * m1()).norm() <= 1e-9 * 3 * K);
  }
  TEST_CASE("VMconst: on the surface the tangent gives stress increments tangent to it") {
    // perfect plasticity: n : D deps = 0 for every deps, n the unit normal s/|s|
    const ConstOut o = VMconst(plasticStrain(), mCst);
    const Vector6d s = devOf(o.Ksig);
    Vector6d nM = s / rhoOf(o.Ksig);  // normal, shear doubled for the tensor contraction
    nM.tail<3>() *= 2;
    const Eigen::Matrix<double, 1, 6> nDm = nM.transpose() * o.D;
    CHECK(nDm.norm() <= 1e-10 * o.D.norm());
    // while the mean stress still responds elastically: m' D = 3K m'
    CHECK((m1().transpose() * o.D).norm() == doctest::Approx(3 * K * std::sqrt(3.0)).epsilon(1e-12));
  }
}
