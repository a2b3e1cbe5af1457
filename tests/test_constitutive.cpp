// Tests of the constitutive models: Hooke3d ([AMPLE] eq 5) and VMconst
// (eq 11, backward-Euler radial return and its algorithmic tangent).
// Voigt order [xx yy zz xy yz zx], strains with engineering shear.
#include "constitutive/Hooke3d.h"
#include "constitutive/VMconst.h"
#include <doctest/doctest.h>
#include <cmath>

using namespace ample;
using Matrix3d = Eigen::Matrix3d;

namespace {
const MaterialConstants mCst{1e6, 0.3, 2e4};  // E, nu, rho_y
const double E = mCst.E, nu = mCst.nu, rhoY = mCst.rhoY;
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

// D by hand from lambda and G (the closed forms below), Voigt [xx yy zz xy yz zx],
// engineering shears
Matrix6d isoD(double E, double nu) {
  const double l = E * nu / ((1 + nu) * (1 - 2 * nu)), g = E / (2 * (1 + nu));
  Matrix6d D = Matrix6d::Zero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) D(i, j) = l;
    D(i, i) = l + 2 * g;
    D(i + 3, i + 3) = g;
  }
  return D;
}
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

// Two more materials, and the properties that hold for every one: the suites call the
// functions with each in turn (an answer that keeps the first material's D, e.g. in a
// static, fails), rotate the strain (isotropy), and check sums and limits by hand.
TEST_SUITE("Hooke3d") {
  // [E, nu, rho_y]: a soft, nearly compressible one and a stiff, nearly incompressible one
  const MaterialConstants matA{2e5, 0.2, 1e3}, matB{7e7, 0.45, 3e5};

  // a strain 6-vector (engineering shears) as a tensor and a stress tensor as a 6-vector
  Matrix3d strainTensor(const Vector6d& e) {
    Matrix3d t;
    t << e(0), e(3) / 2, e(5) / 2, e(3) / 2, e(1), e(4) / 2, e(5) / 2, e(4) / 2, e(2);
    return t;
  }
  Vector6d strainVector(const Matrix3d& t) {
    Vector6d e;
    e << t(0, 0), t(1, 1), t(2, 2), 2 * t(0, 1), 2 * t(1, 2), 2 * t(2, 0);
    return e;
  }
  Matrix3d stressTensor(const Vector6d& s) {
    Matrix3d t;
    t << s(0), s(3), s(5), s(3), s(1), s(4), s(5), s(4), s(2);
    return t;
  }
  Matrix3d rotation3(double a, double b, double c) {  // about z by a, y by b, x by c
    Matrix3d Rz, Ry, Rx;
    Rz << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
    Ry << std::cos(b), 0, std::sin(b), 0, 1, 0, -std::sin(b), 0, std::cos(b);
    Rx << 1, 0, 0, 0, std::cos(c), -std::sin(c), 0, std::sin(c), std::cos(c);
    return Rx * Ry * Rz;
  }
  Vector6d generalStrain() {
    Vector6d e;
    e << 2e-3, -1e-3, 5e-4, 3e-3, -1.5e-3, 8e-4;
    return e;
  }

  TEST_CASE("Hooke3d: two materials in turn / each its own D and stress by hand / none kept from an earlier call") {
    const Vector6d eps = generalStrain();
    // the default material first, then A, B and A again: each answer only from its own E, nu
    for (const MaterialConstants& m : {mCst, matA, matB, matA, mCst, matB}) {
      CAPTURE(m.E);
      CAPTURE(m.nu);
      const Matrix6d Dh = isoD(m.E, m.nu);
      CHECK((elasticStiffness(m.E, m.nu) - Dh).norm() <= 1e-12 * Dh.norm());
      const ConstOut o = Hooke3d(eps, m);
      CHECK((o.D - Dh).norm() <= 1e-12 * Dh.norm());
      // tau = lambda tr(eps) 1 + 2G eps (tensor shears), written out
      const double l = m.E * m.nu / ((1 + m.nu) * (1 - 2 * m.nu)), g = m.E / (2 * (1 + m.nu));
      const double tr = eps(0) + eps(1) + eps(2);
      Vector6d tau;
      tau << l * tr + 2 * g * eps(0), l * tr + 2 * g * eps(1), l * tr + 2 * g * eps(2), g * eps(3), g * eps(4),
          g * eps(5);
      CHECK((o.Ksig - tau).norm() <= 1e-12 * tau.norm());
      CHECK(o.epsE == eps);
    }
  }
  TEST_CASE("Hooke3d: isotropic: the stress of a rotated strain is the rotated stress (two materials and two rotations)") {
    for (const MaterialConstants& m : {matB, matA})
      for (const Matrix3d& Q : {rotation3(0.3, -0.7, 1.1), rotation3(-1.2, 0.4, 0.25)}) {
        const Vector6d eps = generalStrain();
        const Matrix3d tau = stressTensor(Hooke3d(eps, m).Ksig);
        const Vector6d epsR = strainVector(Q * strainTensor(eps) * Q.transpose());
        const Matrix3d tauR = stressTensor(Hooke3d(epsR, m).Ksig);
        CHECK((tauR - Q * tau * Q.transpose()).norm() <= 1e-12 * tau.norm());
      }
  }
  TEST_CASE("Hooke3d: the stored energy eps.D.eps = lambda tr^2 + 2G eps:eps > 0 / rho_y plays no part / the stress is linear in the strain") {
    const Vector6d e1 = generalStrain();
    Vector6d e2;
    e2 << -4e-4, 1e-3, 2e-3, -6e-4, 2e-4, 1e-3;
    for (const MaterialConstants& m : {matA, matB}) {
      const double l = m.E * m.nu / ((1 + m.nu) * (1 - 2 * m.nu)), g = m.E / (2 * (1 + m.nu));
      const Matrix3d t = strainTensor(e1);
      const double W = l * t.trace() * t.trace() + 2 * g * (t.array() * t.array()).sum();
      const ConstOut o = Hooke3d(e1, m);
      CHECK(e1.dot(o.Ksig) == doctest::Approx(W).epsilon(1e-12));
      CHECK(W > 0.0);
      MaterialConstants other = m;
      other.rhoY *= 7.0;  // another yield stress: an elastic law ignores it
      CHECK((Hooke3d(e1, other).Ksig - o.Ksig).norm() <= 1e-14 * o.Ksig.norm());
      const Vector6d s = Hooke3d(2.5 * e1 - 1.5 * e2, m).Ksig;
      CHECK((s - (2.5 * o.Ksig - 1.5 * Hooke3d(e2, m).Ksig)).norm() <= 1e-12 * s.norm());
    }
    // the nearly incompressible B: its uniaxial modulus is far above E (lambda + 2G =
    // E (1 - nu) / ((1 + nu)(1 - 2 nu)) = 7e7 * 0.55 / 0.145 = 265517241.37931034 Pa)
    Vector6d ex = Vector6d::Zero();
    ex(0) = 1e-3;
    CHECK(Hooke3d(ex, matB).Ksig(0) == doctest::Approx(265517.24137931034).epsilon(1e-12));
  }
}

TEST_SUITE("VMconst") {
  // [E, nu, rho_y] of two more materials: a weak and a strong one
  const MaterialConstants weak{2e5, 0.2, 1e3}, strong{7e7, 0.45, 3e6};
  struct Moduli {
    double K, G;
  };
  Moduli moduliOf(const MaterialConstants& m) {
    return {m.E / (3 * (1 - 2 * m.nu)), m.E / (2 * (1 + m.nu))};
  }
  // the trial rho of plasticStrain() for a material, by hand: 2G |e|, |e|^2 = 0.0146625
  double rhoTrialOf(const MaterialConstants& m) { return 2 * moduliOf(m).G * std::sqrt(0.0146625); }
  Matrix6d fdTangent(const Vector6d& eps, const MaterialConstants& m) {
    Matrix6d Dfd;
    const double d = 1e-7 * std::max(1.0, eps.norm() * 10);
    for (int c = 0; c < 6; ++c) {
      Vector6d ep = eps, em = eps;
      ep(c) += d;
      em(c) -= d;
      Dfd.col(c) = (VMconst(ep, m).Ksig - VMconst(em, m).Ksig) / (2 * d);
    }
    return Dfd;
  }
  Matrix3d rot3(double a, double b) {  // about z by a, then about x by b
    Matrix3d Rz, Rx;
    Rz << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
    Rx << 1, 0, 0, 0, std::cos(b), -std::sin(b), 0, std::sin(b), std::cos(b);
    return Rx * Rz;
  }

  TEST_CASE("VMconst: three materials in turn: each returns to its own surface with its own K and G and theta (by hand)") {
    const Vector6d eps = plasticStrain();
    for (const MaterialConstants& m : {weak, mCst, strong, weak}) {
      CAPTURE(m.E);
      const Moduli M = moduliOf(m);
      const double rhoTr = rhoTrialOf(m), theta = m.rhoY / rhoTr;
      REQUIRE(theta < 1.0);  // every one plastic at this strain
      const ConstOut o = VMconst(eps, m);
      CHECK(std::abs(rhoOf(o.Ksig) - m.rhoY) <= 1e-10 * m.rhoY);
      CHECK(meanOf(o.Ksig) == doctest::Approx(3 * M.K * 0.02).epsilon(1e-12));  // p = K tr(eps)
      const Vector6d eVol = 0.02 * m1();
      CHECK((o.epsE - (eVol + theta * (eps - eVol))).norm() <= 1e-12 * eps.norm());
      // the tangent: central differences, symmetric, D m = 3K m, zero along the deviator
      const Matrix6d Dfd = fdTangent(eps, m);
      CHECK((o.D - Dfd).norm() <= 1e-6 * o.D.norm());
      CHECK((o.D - o.D.transpose()).norm() <= 1e-12 * o.D.norm());
      CHECK((o.D * m1() - 3 * M.K * m1()).norm() <= 1e-9 * 3 * M.K);
      Vector6d u = devOf(eps);
      CHECK(rhoOf(o.D * u) <= 1e-9 * 2 * M.G * u.norm());
      // a deviatoric strain w normal to n (n : w = 0, n = s / rho) gets 2G theta w: the
      // trial deviator's part taken out of w = [1 -1 0 0 0 0] (n as an engineering strain)
      Vector6d w = Vector6d::Zero();
      w(0) = 1.0, w(1) = -1.0;
      const Vector6d s = devOf(Hooke3d(eps, m).Ksig), n = s / rhoOf(s);
      Vector6d nEng = n;
      nEng.tail<3>() *= 2;
      w -= n.dot(w) * nEng;                               // n . w is n : w; n . nEng = 1
      const Vector6d Dw = o.D * w;
      Vector6d wStress = w;                               // 2G theta w as a stress: shears halved
      wStress.tail<3>() *= 0.5;
      CHECK((Dw - 2 * M.G * theta * wStress).norm() <= 1e-9 * 2 * M.G * wStress.norm());
    }
  }
  TEST_CASE("VMconst: the same strain is elastic for a strong material and plastic for a weak one") {
    Vector6d eps;
    eps << 1e-2, -2e-2, 5e-3, 1e-2, -4e-3, 7e-3;  // |e_dev| = 0.0245: rho_tr 1.2e6 and 4.1e3 Pa
    const ConstOut s = VMconst(eps, strong), w = VMconst(eps, weak), s2 = VMconst(eps, strong);
    const Moduli S = moduliOf(strong);
    REQUIRE(rhoOf(Hooke3d(eps, strong).Ksig) < strong.rhoY);
    REQUIRE(rhoOf(Hooke3d(eps, weak).Ksig) > weak.rhoY);
    CHECK(s.epsE == eps);
    const double l = S.K - 2 * S.G / 3, tr = eps.head<3>().sum();
    Vector6d tau;  // elastic by hand
    tau << l * tr + 2 * S.G * eps(0), l * tr + 2 * S.G * eps(1), l * tr + 2 * S.G * eps(2), S.G * eps(3),
        S.G * eps(4), S.G * eps(5);
    CHECK((s.Ksig - tau).norm() <= 1e-12 * tau.norm());
    CHECK(std::abs(s.D(3, 3) - S.G) <= 1e-12 * S.G);      // the elastic tangent
    CHECK(std::abs(s.D(0, 1) - l) <= 1e-12 * l);
    CHECK(std::abs(rhoOf(w.Ksig) - weak.rhoY) <= 1e-10 * weak.rhoY);
    CHECK((s2.Ksig - s.Ksig).norm() == 0.0);              // the weak one in between changed nothing
  }
  TEST_CASE("VMconst: a state left on the surface (f of round-off) stands with the elastic tangent / f = 1e-6 returns") {
    for (const MaterialConstants& m : {weak, strong}) {
      const Vector6d dir = devOf(plasticStrain()) + 0.01 * m1();
      const double r0 = rhoOf(Hooke3d(dir, m).Ksig);
      // rho_tr = rho_y (1 + 1e-12): f = 1e-12 <= 1e-9, the trial state stands
      const Vector6d on = dir * (m.rhoY * (1 + 1e-12) / r0);
      const ConstOut o = VMconst(on, m);
      CHECK((o.D - isoD(m.E, m.nu)).norm() <= 1e-12 * o.D.norm());
      CHECK(o.epsE == on);
      // rho_tr = rho_y (1 + 1e-6): returned, no deviatoric stiffness along the deviator
      const Vector6d out = dir * (m.rhoY * (1 + 1e-6) / r0);
      const ConstOut p = VMconst(out, m);
      CHECK(std::abs(rhoOf(p.Ksig) - m.rhoY) <= 1e-12 * m.rhoY);
      Vector6d u = devOf(out);
      CHECK(rhoOf(p.D * u) <= 1e-6 * 2 * moduliOf(m).G * u.norm());
    }
  }
  TEST_CASE("VMconst: isotropic: the return of a rotated strain is the rotated return (two materials)") {
    for (const MaterialConstants& m : {strong, weak})
      for (const Matrix3d& Q : {rot3(0.5, -0.8), rot3(-1.3, 0.2)}) {
        const Vector6d eps = plasticStrain();
        Matrix3d et;
        et << eps(0), eps(3) / 2, eps(5) / 2, eps(3) / 2, eps(1), eps(4) / 2, eps(5) / 2, eps(4) / 2, eps(2);
        const Matrix3d er = Q * et * Q.transpose();
        Vector6d epsR;
        epsR << er(0, 0), er(1, 1), er(2, 2), 2 * er(0, 1), 2 * er(1, 2), 2 * er(2, 0);
        const Vector6d a = VMconst(eps, m).Ksig, b = VMconst(epsR, m).Ksig;
        Matrix3d ta, tb;
        ta << a(0), a(3), a(5), a(3), a(1), a(4), a(5), a(4), a(2);
        tb << b(0), b(3), b(5), b(3), b(1), b(4), b(5), b(4), b(2);
        CHECK((tb - Q * ta * Q.transpose()).norm() <= 1e-10 * ta.norm());
      }
  }
}

// rho_y against the strengths a soil engineer gives (setups.cpp's help of rhoY, docs/setups.md):
// at yield rho = sqrt(2 J2) = rho_y; plane-strain shear (simple or pure) reaches
// tau_max = rho_y / sqrt(2) = c_u, and an isochoric axisymmetric strain reaches
// sigma_1 - sigma_3 = sqrt(3/2) rho_y = sigma_y. The expected values are the hand ones of
// rhoY = 14142.1356 (c_u = 10 kPa): c_u = 10000 Pa, sigma_y = sqrt(3) c_u = 17320.508 Pa.
TEST_SUITE("VMconst") {
  // the stress reached by driving a strain path in 200 equal increments through VMconst
  // (the elastic strain carried from one increment to the next, as detMPs carries epsEn)
  Vector6d driven(const Vector6d& total, const MaterialConstants& m) {
    Vector6d epsE = Vector6d::Zero(), tau = Vector6d::Zero();
    for (int k = 0; k < 200; ++k) {
      const ConstOut out = VMconst(epsE + total / 200, m);
      epsE = out.epsE, tau = out.Ksig;
    }
    return tau;
  }
  double tauMax(const Vector6d& s) {  // the largest in-plane shear stress (Mohr's circle)
    return std::sqrt(0.25 * (s(0) - s(1)) * (s(0) - s(1)) + s(3) * s(3));
  }

  TEST_CASE("VMconst: rhoY = sqrt(2) c_u: plane-strain simple and pure shear yield at tau_max = 10 kPa, uniaxial at 17.32 kPa") {
    const MaterialConstants soil{1e7, 0.49, 14142.1356};        // undrained: nu near 0.5
    const double cu = 10000.0, sigmaY = 17320.508;              // by hand
    const double Gs = soil.E / (2 * (1 + soil.nu));             // 3.356e6 Pa: yield at gamma ~ 3e-3
    Vector6d simple = Vector6d::Zero(), pure = Vector6d::Zero(), axi = Vector6d::Zero();
    simple(3) = 0.05;                                           // gamma_xy, 17 times the yield strain
    pure << 0.025, -0.025, 0, 0, 0, 0;                          // eps_xx = -eps_yy, eps_zz = 0
    axi << 0.04, -0.02, -0.02, 0, 0, 0;                         // isochoric, axisymmetric about x
    const Vector6d s1 = driven(simple, soil), s2 = driven(pure, soil), s3 = driven(axi, soil);
    CHECK(tauMax(s1) == doctest::Approx(cu).epsilon(1e-8));
    CHECK(tauMax(s2) == doctest::Approx(cu).epsilon(1e-8));
    CHECK(s3(0) - s3(1) == doctest::Approx(sigmaY).epsilon(1e-7));
    CHECK(s3(1) == doctest::Approx(s3(2)).epsilon(1e-12));
    // before yield the same paths are elastic: a tenth of the yield strain gives G gamma
    Vector6d small = Vector6d::Zero();
    small(3) = 0.1 * cu / Gs;
    CHECK(tauMax(driven(small, soil)) == doctest::Approx(0.1 * cu).epsilon(1e-10));
  }
}
