// Tests of the constitutive models: Hooke3d (eq 5) and VMconst (eq 11,
// backward-Euler return and algorithmic tangent).
#include "constitutive/Hooke3d.h"
#include "constitutive/VMconst.h"
#include <doctest/doctest.h>
#include <cmath>

using namespace ample;

namespace {
const Vector3d mCst(1e6, 0.3, 2e4);  // E, nu, rho_y
double rhoOf(const Vector6d& s) {    // sqrt(2 J2)
  const double p = s.head<3>().sum() / 3.0;
  return std::sqrt((s.head<3>().array() - p).square().sum() + 2 * s.tail<3>().squaredNorm());
}
}  // namespace

TEST_SUITE("Hooke3d") {
  TEST_CASE("Hooke3d: uniaxial strain and pure shear against the Lame relations") {
    const double E = mCst(0), nu = mCst(1);
    const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), G = E / (2 * (1 + nu));
    Vector6d eps = Vector6d::Zero();
    eps(0) = 1e-3;
    ConstOut o = Hooke3d(eps, mCst);
    CHECK(o.Ksig(0) == doctest::Approx((lam + 2 * G) * 1e-3).epsilon(1e-14));
    CHECK(o.Ksig(1) == doctest::Approx(lam * 1e-3).epsilon(1e-14));
    CHECK(o.epsE == eps);
    eps.setZero();
    eps(3) = 2e-3;  // engineering shear gamma_xy
    o = Hooke3d(eps, mCst);
    CHECK(o.Ksig(3) == doctest::Approx(G * 2e-3).epsilon(1e-14));
    CHECK((o.D - o.D.transpose()).norm() == 0.0);
  }
}

TEST_SUITE("VMconst") {
  TEST_CASE("VMconst: inside the surface the trial state stands with the elastic tangent") {
    Vector6d eps;
    eps << 1e-3, -2e-3, 5e-4, 1e-3, 0, 0;
    const ConstOut o = VMconst(eps, mCst), e = Hooke3d(eps, mCst);
    REQUIRE(rhoOf(e.Ksig) < mCst(2));
    CHECK(o.Ksig == e.Ksig);
    CHECK(o.D == e.D);
  }
  TEST_CASE("VMconst: a trial state outside returns onto the surface radially") {
    Vector6d eps;
    eps << 0.03, -0.02, 0.01, 0.015, -0.01, 0.02;
    const ConstOut o = VMconst(eps, mCst), e = Hooke3d(eps, mCst);
    REQUIRE(rhoOf(e.Ksig) > 1.5 * mCst(2));  // well outside the surface
    CHECK(std::abs(rhoOf(o.Ksig) - mCst(2)) <= 1e-10 * mCst(2));
    CHECK(o.Ksig.head<3>().sum() == doctest::Approx(e.Ksig.head<3>().sum()).epsilon(1e-13));
    Vector6d m;
    m << 1, 1, 1, 0, 0, 0;
    const Vector6d sT = e.Ksig - e.Ksig.head<3>().mean() * m, s = o.Ksig - o.Ksig.head<3>().mean() * m;
    CHECK((s / s.norm() - sT / sT.norm()).norm() <= 1e-13);          // same direction
    CHECK((Hooke3d(o.epsE, mCst).Ksig - o.Ksig).norm() <= 1e-10 * o.Ksig.norm());
  }
  TEST_CASE("VMconst: algorithmic tangent equals central differences of the return map") {
    Vector6d eps;
    eps << 0.03, -0.02, 0.01, 0.015, -0.01, 0.02;
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
  }
}
