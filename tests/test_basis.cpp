// Tests of the basis functions: SvpMPM, SvpGIMP ([AMPLE] eqs 23-26), MPMbasis
// (eq 22) and elemMPinfo: partition of unity, linear reproduction, gradients
// against finite differences, continuity across the GIMP regions, GIMP = MPM
// inside a cell. The points are built by hand on a grid from formCoord2D.
#include "ample/basis/MPMbasis.h"
#include "ample/basis/SvpGIMP.h"
#include "ample/basis/SvpMPM.h"
#include "ample/elemMPinfo.h"
#include "setups/formCoord2D.h"
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>

using namespace ample;

namespace {
const double h = 0.5, lp = 0.1;  // grid spacing and domain half length (lp <= h/2)

// sums over the nodes of a 1D grid (nodes at k h, k = -4..12) at position x:
// S, dS and the reproduced position sum_v S_v x_v
struct Sums {
  double S = 0, dS = 0, x = 0;
};
Sums sum1D(double x, bool gimp, double l = lp) {
  Sums s;
  for (int k = -4; k <= 12; ++k) {
    const Basis1D b = gimp ? SvpGIMP(x - k * h, h, l) : SvpMPM(x - k * h, h);
    s.S += b.S;
    s.dS += b.dS;
    s.x += b.S * k * h;
  }
  return s;
}

// a point of the given type at x with domain half lengths l, linked to every
// node of a 3 x 3 grid of 1 m cells (16 nodes = MAXN): nodes outside the
// support simply get S = 0, so MPMbasis is tested without the cell search
MaterialPoint pointOnAllNodes(const Mesh& mesh, MpType t, Vector2d x, Vector2d l) {
  MaterialPoint mp;
  mp.mpType = t;
  mp.mpC = x;
  mp.lp = (t == MpType::GIMP) ? l : Vector2d::Zero();
  mp.nn = mesh.nodes();
  for (int v = 0; v < mp.nn; ++v) mp.nIN[v] = v;
  return mp;
}

// invariants of a linear-complete basis at one point:
// sum S = 1, sum S X = x, sum dS = 0, sum X (x) dS = I
struct Invariants {
  double unity, position, gradSum, gradX;  // absolute errors
};
Invariants invariants(const Mesh& mesh, const MaterialPoint& mp) {
  double S = 0;
  Vector2d x = Vector2d::Zero(), dS = Vector2d::Zero();
  Eigen::Matrix2d gradX = Eigen::Matrix2d::Zero();
  for (int v = 0; v < mp.nn; ++v) {
    const Vector2d Xv = mesh.coord.row(mp.nIN[v]).transpose();
    S += mp.Svp[v];
    x += mp.Svp[v] * Xv;
    dS += mp.dSvp.col(v);
    gradX += Xv * mp.dSvp.col(v).transpose();
  }
  return {std::abs(S - 1.0), (x - mp.mpC).norm(), dS.norm(),
          (gradX - Eigen::Matrix2d::Identity()).norm()};
}
// the 1D hat of eqs 23-24 (d off the nodes) and its average over [d - l, d + l] (eq 20),
// written out here independently of SvpMPM and SvpGIMP
double hatRef(double d, double hh) { return std::max(0.0, 1.0 - std::abs(d) / hh); }
double hatSlopeRef(double d, double hh) {
  return std::abs(d) >= hh ? 0.0 : (d > 0 ? -1.0 : 1.0) / hh;
}
double hatAvgRef(double d, double hh, double l) {
  if (l == 0) return hatRef(d, hh);
  const auto F = [hh](double s) {  // int_0^s of the hat
    s = std::clamp(s, -hh, hh);
    return s - s * std::abs(s) / (2 * hh);
  };
  return (F(d + l) - F(d - l)) / (2 * l);
}
double hatAvgSlopeRef(double d, double hh, double l) {
  return l == 0 ? hatSlopeRef(d, hh) : (hatRef(d + l, hh) - hatRef(d - l, hh)) / (2 * l);
}
}  // namespace

TEST_SUITE("SvpMPM") {
  TEST_CASE("SvpMPM: partition of unity / zero gradient sum / linear reproduction") {
    for (double x = 0.013; x < 4.0; x += 0.0371) {
      CAPTURE(x);
      const Sums s = sum1D(x, false);
      CHECK(std::abs(s.S - 1.0) <= 1e-14);
      CHECK(std::abs(s.dS) <= 1e-12);
      CHECK(std::abs(s.x - x) <= 1e-13);
    }
  }
  TEST_CASE("SvpMPM: values of eq 23 and gradients of eq 24") {
    CHECK(SvpMPM(0.0, h).S == 1.0);
    CHECK(SvpMPM(-0.2, h).S == doctest::Approx(0.6).epsilon(1e-14));
    CHECK(SvpMPM(-0.2, h).dS == doctest::Approx(2.0).epsilon(1e-14));
    CHECK(SvpMPM(0.2, h).S == doctest::Approx(0.6).epsilon(1e-14));
    CHECK(SvpMPM(0.2, h).dS == doctest::Approx(-2.0).epsilon(1e-14));
    CHECK(SvpMPM(0.6, h).S == 0.0);
    CHECK(SvpMPM(-0.6, h).dS == 0.0);
  }
  TEST_CASE("SvpMPM: within round-off of a node the gradient is that of the point on the node") {
    // the same side as elemForMP's cell: d = +-4e-16 both take the left branch (x <= X_v),
    // and the node one cell to the left (d = h + 4e-16) keeps its gradient
    CHECK(SvpMPM(4e-16, h).dS == 2.0);
    CHECK(SvpMPM(-4e-16, h).dS == 2.0);
    CHECK(SvpMPM(h + 4e-16, h).dS == -2.0);
    CHECK(SvpMPM(-h + 4e-16, h).dS == 0.0);
    CHECK(SvpMPM(1e-6, h).dS == -2.0);                  // really right of the node
    CHECK(SvpMPM(4e-16, h).S == doctest::Approx(1.0));  // the value is continuous
  }
  TEST_CASE("SvpMPM: spacings 0.3 / 2 / 1e4 / 1e-3 in turn: hand values / zero outside the support / unity and reproduction on shifted grids") {
    // each spacing twice, after the others: nothing of one call may be kept for the next;
    // node positions x0 + k hh with an origin x0 off zero
    const double hs[4] = {0.3, 2.0, 1e4, 1e-3}, x0s[4] = {-1.7, 3.25, 2.5e4, 0.0123};
    for (int rep = 0; rep < 2; ++rep)
      for (int g = 0; g < 4; ++g) {
        const double hh = hs[g], x0 = x0s[g];
        CAPTURE(hh);
        // eq 23-24 by hand: d = h/4 -> S = 3/4, dS = -1/h; d = -0.6 h -> S = 0.4, dS = 1/h
        CHECK(SvpMPM(0.25 * hh, hh).S == doctest::Approx(0.75).epsilon(1e-14));
        CHECK(SvpMPM(0.25 * hh, hh).dS == doctest::Approx(-1.0 / hh).epsilon(1e-14));
        CHECK(SvpMPM(-0.6 * hh, hh).S == doctest::Approx(0.4).epsilon(1e-14));
        CHECK(SvpMPM(-0.6 * hh, hh).dS == doctest::Approx(1.0 / hh).epsilon(1e-14));
        // zero (exactly) outside the support |d| <= h, also just past its ends
        for (double f : {1.0001, 1.5, 3.0, -1.0001, -2.5, -1.0 - 1e-7}) {
          CAPTURE(f);
          CHECK(SvpMPM(f * hh, hh).S == 0.0);
          CHECK(SvpMPM(f * hh, hh).dS == 0.0);
        }
        // a sweep over three cells: sum S = 1, sum dS = 0, sum S X = x, 0 <= S <= 1, and
        // dS against central differences of S (away from the nodes)
        for (int k = 0; k < 60; ++k) {
          const double x = x0 + (0.5031 + 0.0487 * k) * hh;
          CAPTURE(x);
          double S = 0, dS = 0, X = 0;
          for (int n = -2; n <= 7; ++n) {
            const double Xn = x0 + n * hh;
            const Basis1D b = SvpMPM(x - Xn, hh);
            CHECK(b.S >= 0.0);
            CHECK(b.S <= 1.0);
            S += b.S, dS += b.dS, X += b.S * (Xn - x0);
            const double e = 1e-6 * hh;
            const double fd = (SvpMPM(x - Xn + e, hh).S - SvpMPM(x - Xn - e, hh).S) / (2 * e);
            CHECK(std::abs(fd - b.dS) * hh <= 1e-6);
          }
          CHECK(std::abs(S - 1.0) <= 1e-13);
          CHECK(std::abs(dS) * hh <= 1e-12);
          CHECK(std::abs(X - (x - x0)) <= 1e-12 * hh);
        }
      }
  }
  TEST_CASE("SvpMPM: the round-off rule is relative to h (t = 1e-9 h) for h = 1e4 and 1e-3") {
    for (double hh : {1e4, 1e-3, 0.5, 1e4}) {
      CAPTURE(hh);
      CHECK(SvpMPM(1e-11 * hh, hh).dS == 1.0 / hh);         // on the node: the left branch
      CHECK(SvpMPM(-1e-11 * hh, hh).dS == 1.0 / hh);
      CHECK(SvpMPM(1e-7 * hh, hh).dS == -1.0 / hh);         // really right of the node
      CHECK(SvpMPM(-1e-7 * hh, hh).dS == 1.0 / hh);
      CHECK(SvpMPM((1 + 1e-11) * hh, hh).dS == -1.0 / hh);  // the node one cell to the left
      CHECK(SvpMPM((1 + 1e-11) * hh, hh).S == 0.0);         // ... whose value is 0 there
      CHECK(SvpMPM((1 + 1e-7) * hh, hh).dS == 0.0);
      CHECK(SvpMPM((-1 + 1e-11) * hh, hh).dS == 0.0);
      CHECK(SvpMPM((-1 + 1e-7) * hh, hh).dS == 1.0 / hh);
    }
  }
}

TEST_SUITE("SvpGIMP") {
  TEST_CASE("SvpGIMP: partition of unity / zero gradient sum / linear reproduction for lp <= h/2") {
    for (double l : {lp, 0.01, h / 2}) {  // h/2: the widest domain allowed (regions B, D vanish)
      for (double x = 0.013; x < 4.0; x += 0.0371) {
        CAPTURE(l);
        CAPTURE(x);
        const Sums s = sum1D(x, true, l);
        CHECK(std::abs(s.S - 1.0) <= 1e-14);
        CHECK(std::abs(s.dS) <= 1e-12);
        CHECK(std::abs(s.x - x) <= 1e-13);
      }
    }
  }
  TEST_CASE("SvpGIMP: gradient equals central differences and hand values in each region A-E") {
    // regions: A A B C C D E E, all at least 0.05 away from a region boundary; the hand
    // values of eq 26 (h = 0.5, lp = 0.1, 2 h lp = 0.1): A (h+l+d)/0.1 = 0.5, 1.5; B 1/h = 2;
    // C -d/(h l) = 1, -1.4; D -2; E -(h+l-d)/0.1 = -1.5, -0.5
    const double d[8] = {-0.55, -0.45, -0.3, -0.05, 0.07, 0.3, 0.45, 0.55};
    const double dS[8] = {0.5, 1.5, 2.0, 1.0, -1.4, -2.0, -1.5, -0.5};
    for (int k = 0; k < 8; ++k) {
      CAPTURE(d[k]);
      const double e = 1e-6;
      const double fd = (SvpGIMP(d[k] + e, h, lp).S - SvpGIMP(d[k] - e, h, lp).S) / (2 * e);
      CHECK(std::abs(SvpGIMP(d[k], h, lp).dS - fd) <= 1e-6);
      CHECK(std::abs(SvpGIMP(d[k], h, lp).dS - dS[k]) <= 1e-12);
      CHECK(std::abs(fd - dS[k]) <= 1e-6);  // the value S itself has this slope
    }
  }
  TEST_CASE("SvpGIMP: value and gradient continuous across the region boundaries / with their hand values") {
    // A|B, B|C, C|D, D|E, and the outer ends of A and E (where S and dS reach 0); at
    // d = -h+l: S = (2l)^2/(4hl) = l/h = 0.2, dS = 2l/(2hl) = 1/h = 2; at d = -l: S = 1 - l/h = 0.8,
    // dS = l/(hl) = 2 (mirrored for d > 0)
    const double b[6] = {-h + lp, -lp, lp, h - lp, -h - lp, h + lp};
    const double S[6] = {0.2, 0.8, 0.8, 0.2, 0.0, 0.0}, dS[6] = {2.0, 2.0, -2.0, -2.0, 0.0, 0.0};
    for (int k = 0; k < 6; ++k) {
      CAPTURE(b[k]);
      const Basis1D lo = SvpGIMP(b[k] - 1e-9, h, lp), hi = SvpGIMP(b[k] + 1e-9, h, lp);
      CHECK(std::abs(lo.S - hi.S) <= 1e-7);
      CHECK(std::abs(lo.dS - hi.dS) <= 1e-7);
      CHECK(std::abs(lo.S - S[k]) <= 1e-7);
      CHECK(std::abs(lo.dS - dS[k]) <= 1e-7);
    }
  }
  TEST_CASE("SvpGIMP: equals standard MPM when the domain lies inside one cell") {
    for (double d : {-0.35, -0.2, -0.12, 0.12, 0.25, 0.38}) {  // regions B and D
      CAPTURE(d);
      CHECK(SvpGIMP(d, h, lp).S == doctest::Approx(SvpMPM(d, h).S).epsilon(1e-14));
      CHECK(SvpGIMP(d, h, lp).dS == doctest::Approx(SvpMPM(d, h).dS).epsilon(1e-14));
    }
    CHECK(SvpGIMP(0.2, h, 0.0).S == SvpMPM(0.2, h).S);  // lp = 0 is standard MPM
  }
  TEST_CASE("SvpGIMP: the convolution of eq 20 in regions C and A") {
    // S = (1/2lp) int_{d-lp}^{d+lp} N(s) ds, N the hat function 1 - |s|/h
    const auto hatIntegral = [](double a, double b) {  // int_a^b (1 - |s|/h) ds, |a|,|b| <= h
      const auto F = [](double s) { return s - s * std::abs(s) / (2 * h); };
      return F(b) - F(a);
    };
    const double dC = 0.04, dA = -0.52;  // region C, and region A (only d+lp > -h overlaps)
    CHECK(SvpGIMP(dC, h, lp).S ==
          doctest::Approx(hatIntegral(dC - lp, dC + lp) / (2 * lp)).epsilon(1e-13));
    CHECK(SvpGIMP(dA, h, lp).S ==
          doctest::Approx(hatIntegral(-h, dA + lp) / (2 * lp)).epsilon(1e-13));
  }
  TEST_CASE("SvpGIMP: spacings 0.3 / 2 / 7.5 and lp = h/4 / h/2 in turn: hand values of each region / zero outside") {
    // h = 1, l = 1/4 (4hl = 1, 2hl = 1/2, hl = 1/4), d/h in each region:
    //   A d = -1.1: S = 0.15^2 = 0.0225, dS = 0.15/0.5 = 0.3   B d = -0.5: S = 0.5, dS = 1
    //   C d = 0.1:  S = 1 - (0.01 + 0.0625)/0.5 = 0.855, dS = -0.1/0.25 = -0.4
    //   D d = 0.6:  S = 0.4, dS = -1                           E d = 1.0: S = 0.25^2 = 0.0625, dS = -0.5
    // h = 1, l = 1/2 (B, D vanish): A d = -0.9: S = 0.6^2/2 = 0.18, dS = 0.6; C d = 0.3: S = 1 - 0.34 = 0.66,
    //   dS = -0.6; E d = 0.8: S = 0.7^2/2 = 0.245, dS = -0.7
    // for h and l = a h: S is the same at d = f h, dS is divided by h
    struct Row { double a, f, S, dS; };
    const Row rows[] = {{0.25, -1.1, 0.0225, 0.3}, {0.25, -0.5, 0.5, 1.0}, {0.25, 0.1, 0.855, -0.4},
                        {0.25, 0.6, 0.4, -1.0},    {0.25, 1.0, 0.0625, -0.5}, {0.5, -0.9, 0.18, 0.6},
                        {0.5, 0.3, 0.66, -0.6},    {0.5, 0.8, 0.245, -0.7}};
    for (int rep = 0; rep < 2; ++rep)
      for (double hh : {0.3, 2.0, 7.5}) {
        for (const Row& r : rows) {
          CAPTURE(hh);
          CAPTURE(r.a);
          CAPTURE(r.f);
          const Basis1D b = SvpGIMP(r.f * hh, hh, r.a * hh);
          CHECK(std::abs(b.S - r.S) <= 1e-13);
          CHECK(std::abs(b.dS * hh - r.dS) <= 1e-13);
        }
        for (double a : {0.1, 0.25, 0.5})  // zero at and beyond |d| = h + l
          for (double f : {1.0, 1.01, 2.0, -1.01, -3.0}) {
            CAPTURE(hh);
            CAPTURE(a);
            CAPTURE(f);
            const Basis1D b = SvpGIMP((f > 0 ? f + a : f - a) * hh, hh, a * hh);
            CHECK(std::abs(b.S) <= 1e-15);
            CHECK(std::abs(b.dS) * hh <= 1e-14);
          }
      }
  }
  TEST_CASE("SvpGIMP: unity / reproduction / central differences / continuity for h = 0.3 / 2 / 7.5 on shifted grids") {
    for (int rep = 0; rep < 2; ++rep)
      for (double hh : {0.3, 2.0, 7.5})
        for (double a : {0.1, 0.37, 0.5}) {
          const double l = a * hh, x0 = -1.3 * hh;  // nodes x0 + n hh
          CAPTURE(hh);
          CAPTURE(l);
          for (int k = 0; k < 40; ++k) {
            const double x = x0 + (0.5017 + 0.0743 * k) * hh;
            CAPTURE(x);
            double S = 0, dS = 0, X = 0;
            for (int n = -2; n <= 7; ++n) {
              const Basis1D b = SvpGIMP(x - (x0 + n * hh), hh, l);
              S += b.S, dS += b.dS, X += b.S * n * hh;
              const double e = 1e-7 * hh, d = x - (x0 + n * hh);
              const double fd = (SvpGIMP(d + e, hh, l).S - SvpGIMP(d - e, hh, l).S) / (2 * e);
              CHECK(std::abs(fd - b.dS) * hh <= 1e-5);
            }
            CHECK(std::abs(S - 1.0) <= 1e-13);
            CHECK(std::abs(dS) * hh <= 1e-12);
            CHECK(std::abs(X - (x - x0)) <= 1e-12 * hh);
          }
          // the region boundaries: S and dS continuous, S = l/h and 1 - l/h, dS = +-1/h there
          const double b[6] = {-hh - l, -hh + l, -l, l, hh - l, hh + l};
          const double Sb[6] = {0, a, 1 - a, 1 - a, a, 0}, dSb[6] = {0, 1, 1, -1, -1, 0};
          for (int k = 0; k < 6; ++k) {
            CAPTURE(k);
            const double e = 1e-10 * hh;
            const Basis1D lo = SvpGIMP(b[k] - e, hh, l), hi = SvpGIMP(b[k] + e, hh, l);
            CHECK(std::abs(lo.S - hi.S) <= 1e-8);
            CHECK(std::abs(lo.dS - hi.dS) * hh <= 1e-8);
            CHECK(std::abs(lo.S - Sb[k]) <= 1e-8);
            CHECK(std::abs(lo.dS * hh - dSb[k]) <= 1e-8);
          }
        }
  }
}

TEST_SUITE("MPMbasis") {
  TEST_CASE("MPMbasis: 2D partition of unity / zero gradient sum / sum dS (x) X = I / MPM and GIMP") {
    const Mesh mesh = formCoord2D(3, 3, 3.0, 3.0);  // 16 nodes, h = 1
    const Vector2d l(0.2, 0.3);                      // GIMP domain half lengths
    for (MpType t : {MpType::MPM, MpType::GIMP}) {
      // inside a cell, straddling a vertical edge, a horizontal edge, a corner
      for (Vector2d x : {Vector2d(1.45, 1.6), Vector2d(1.9, 1.5), Vector2d(1.37, 2.1),
                         Vector2d(2.05, 0.92), Vector2d(0.4, 2.5)}) {
        CAPTURE(int(t));
        CAPTURE(x.transpose());
        MaterialPoint mp = pointOnAllNodes(mesh, t, x, l);
        MPMbasis(mesh, mp);
        const Invariants e = invariants(mesh, mp);
        CHECK(e.unity <= 1e-14);
        CHECK(e.position <= 1e-13);
        CHECK(e.gradSum <= 1e-12);
        CHECK(e.gradX <= 1e-12);
      }
    }
  }
  TEST_CASE("MPMbasis: S(X Y) = S(X) S(Y) and gradients are its partial derivatives") {
    const Mesh mesh = formCoord2D(3, 3, 3.0, 3.0);
    MaterialPoint mp = pointOnAllNodes(mesh, MpType::GIMP, Vector2d(1.93, 2.08), Vector2d(0.2, 0.15));
    MPMbasis(mesh, mp);
    for (int v = 0; v < mp.nn; ++v) {  // eq 22 and footnote 3, from the 1D functions
      const Vector2d d = mp.mpC - mesh.coord.row(v).transpose();
      const Basis1D bx = SvpGIMP(d(0), 1.0, 0.2), by = SvpGIMP(d(1), 1.0, 0.15);
      CHECK(std::abs(mp.Svp[v] - bx.S * by.S) <= 1e-15);
      CHECK(std::abs(mp.dSvp(0, v) - bx.dS * by.S) <= 1e-14);
      CHECK(std::abs(mp.dSvp(1, v) - bx.S * by.dS) <= 1e-14);
    }
    const double e = 1e-6;  // and the gradients against central differences
    for (int i = 0; i < nD; ++i) {
      MaterialPoint p = pointOnAllNodes(mesh, MpType::GIMP, mp.mpC, mp.lp);  // a basis of their own
      MaterialPoint m = p;                                                  // (a copy shares it)
      m.nn = mp.nn;
      for (int v = 0; v < mp.nn; ++v) m.nIN[v] = p.nIN[v];
      p.mpC(i) += e;
      m.mpC(i) -= e;
      MPMbasis(mesh, p);
      MPMbasis(mesh, m);
      for (int v = 0; v < mp.nn; ++v) {
        CAPTURE(i);
        CAPTURE(v);
        CHECK(std::abs((p.Svp[v] - m.Svp[v]) / (2 * e) - mp.dSvp(i, v)) <= 1e-6);
      }
    }
  }
  TEST_CASE("MPMbasis: cells of h_x != h_y / a shifted origin / nodes listed in reverse: S and dS by hand") {
    // two grids in turn (twice): h = (0.5, 0.8) from the origin (-0.7, 1.9), 16 nodes, and
    // h = (2, 0.5) from 0, 15 nodes; the point lists the nodes in reverse order (nIN[v] != v);
    // reference: the hat and its domain average by hand (hatRef, hatAvgRef) in x times y
    Mesh m1 = formCoord2D(3, 3, 1.5, 2.4);
    m1.origin = Vector2d(-0.7, 1.9);
    m1.coord.rowwise() += m1.origin.transpose();
    const Mesh m2 = formCoord2D(4, 2, 8.0, 1.0);
    const Mesh* meshes[2] = {&m1, &m2};
    const Vector2d lps[2] = {Vector2d(0.1, 0.3), Vector2d(0.7, 0.15)};
    const Vector2d pts[2][3] = {{Vector2d(-0.31, 2.47), Vector2d(0.29, 3.13), Vector2d(0.07, 3.52)},
                                {Vector2d(3.1, 0.37), Vector2d(4.35, 0.52), Vector2d(5.93, 0.26)}};
    for (int rep = 0; rep < 2; ++rep)
      for (int g = 0; g < 2; ++g)
        for (MpType t : {MpType::MPM, MpType::GIMP})
          for (const Vector2d& x : pts[g]) {
            const Mesh& mesh = *meshes[g];
            CAPTURE(g);
            CAPTURE(int(t));
            CAPTURE(x.transpose());
            MaterialPoint mp = pointOnAllNodes(mesh, t, x, lps[g]);
            for (int v = 0; v < mp.nn; ++v) mp.nIN[v] = mp.nn - 1 - v;
            MPMbasis(mesh, mp);
            for (int v = 0; v < mp.nn; ++v) {
              CAPTURE(v);
              const int n = mp.nIN[v];
              const Vector2d d = x - mesh.coord.row(n).transpose();
              const double hx = mesh.h(0), hy = mesh.h(1), lx = mp.lp(0), ly = mp.lp(1);
              const double Sx = hatAvgRef(d(0), hx, lx), Sy = hatAvgRef(d(1), hy, ly);
              CHECK(std::abs(mp.Svp[v] - Sx * Sy) <= 1e-14);
              CHECK(std::abs(mp.dSvp(0, v) - hatAvgSlopeRef(d(0), hx, lx) * Sy) <= 1e-13);
              CHECK(std::abs(mp.dSvp(1, v) - Sx * hatAvgSlopeRef(d(1), hy, ly)) <= 1e-13);
            }
            const Invariants e = invariants(mesh, mp);
            CHECK(e.unity <= 1e-14);
            CHECK(e.position <= 1e-13);
            CHECK(e.gradSum <= 1e-12);
            CHECK(e.gradX <= 1e-12);
          }
  }
  TEST_CASE("MPMbasis: a point linked to its own cell's four nodes only (in the order of the cell)") {
    // h = (0.5, 0.8): the point (0.62, 1.13) lies in cell (1, 1) of 3 x 3; its nodes 5, 6, 10, 9
    const Mesh mesh = formCoord2D(3, 3, 1.5, 2.4);
    MaterialPoint mp;
    mp.mpType = MpType::MPM;
    mp.mpC = Vector2d(0.62, 1.13);
    mp.nn = 4;
    const int nodes[4] = {5, 6, 10, 9};
    for (int v = 0; v < 4; ++v) mp.nIN[v] = nodes[v];
    MPMbasis(mesh, mp);
    // local (x - 0.5)/0.5 = 0.24, (y - 0.8)/0.8 = 0.4125: S = (1-0.24)(1-0.4125), 0.24 (1-0.4125),
    // 0.24 0.4125, (1-0.24) 0.4125; dS/dx = -+(1-0.4125)/0.5, +-0.4125/0.5; dS/dy by y
    const double u = 0.24, w = 0.4125;
    const double S[4] = {(1 - u) * (1 - w), u * (1 - w), u * w, (1 - u) * w};
    const double gx[4] = {-(1 - w) / 0.5, (1 - w) / 0.5, w / 0.5, -w / 0.5};
    const double gy[4] = {-(1 - u) / 0.8, -u / 0.8, u / 0.8, (1 - u) / 0.8};
    for (int v = 0; v < 4; ++v) {
      CAPTURE(v);
      CHECK(std::abs(mp.Svp[v] - S[v]) <= 1e-14);
      CHECK(std::abs(mp.dSvp(0, v) - gx[v]) <= 1e-13);
      CHECK(std::abs(mp.dSvp(1, v) - gy[v]) <= 1e-13);
    }
  }
}

TEST_SUITE("elemMPinfo") {
  TEST_CASE("elemMPinfo: linked nodes carry a complete linear basis / active cells marked") {
    for (MpType t : {MpType::MPM, MpType::GIMP}) {
      Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);
      std::vector<MaterialPoint> pts(3);
      const Vector2d x[3] = {Vector2d(1.5, 1.5), Vector2d(2.05, 1.3), Vector2d(2.95, 3.05)};
      for (int p = 0; p < 3; ++p) {
        pts[p].mpType = t;
        pts[p].mpC = x[p];
        pts[p].lp = (t == MpType::GIMP) ? Vector2d(0.25, 0.25) : Vector2d::Zero();
      }
      elemMPinfo(mesh, pts);
      for (const MaterialPoint& mp : pts) {
        CAPTURE(int(t));
        CAPTURE(mp.mpC.transpose());
        const Invariants e = invariants(mesh, mp);
        CHECK(e.unity <= 1e-14);
        CHECK(e.position <= 1e-13);
        CHECK(e.gradSum <= 1e-12);
        CHECK(e.gradX <= 1e-12);
      }
      // cells holding a point (MPM) or overlapped by a domain (GIMP) are active
      std::vector<int> active;
      for (int c = 0; c < mesh.nels(); ++c)
        if (mesh.eInA[c]) active.push_back(c);
      if (t == MpType::MPM)
        CHECK(active == std::vector<int>{5, 6, 14});
      else  // [1.25,1.75]^2 -> 5; [1.8,2.3]x[1.05,1.55] -> 5,6; [2.7,3.2]x[2.8,3.3] -> 10,11,14,15
        CHECK(active == std::vector<int>{5, 6, 10, 11, 14, 15});
    }
  }
}
