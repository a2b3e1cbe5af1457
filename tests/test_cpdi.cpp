// Tests of the CPDI basis functions ([CPDI] sec 2 (iv)): SvpCPDI1, SvpCPDI2,
// cpdi2Weights, and CPDI points through MPMbasis / elemMPinfo. The reference
// values are computed independently here: the grid hat functions by hand and
// the domain averages by 3 x 3 Gauss quadrature of the isoparametric map of the
// domain (exact, since every integrand is at most quadratic in xi and eta).
#include "ample/basis/MPMbasis.h"
#include "ample/cpdi/SvpCPDI.h"
#include "ample/cpdi/domainCorners.h"
#include "ample/cpdi/elemMPinfoCPDI.h"
#include "setups/formCoord2D.h"
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>

using namespace ample;

namespace {
const double xiC[4] = {-1, 1, 1, -1}, etaC[4] = {-1, -1, 1, 1};  // corner local coordinates

// bi-linear grid hat function of node n at x, written out independently of the library
double hat(const Mesh& mesh, int n, const Vector2d& x) {
  const double ax = 1.0 - std::abs(x(0) - mesh.coord(n, 0)) / mesh.h(0);
  const double ay = 1.0 - std::abs(x(1) - mesh.coord(n, 1)) / mesh.h(1);
  return std::max(ax, 0.0) * std::max(ay, 0.0);
}
// gradient of the hat function (x strictly inside a cell)
Vector2d hatGrad(const Mesh& mesh, int n, const Vector2d& x) {
  const double dx = x(0) - mesh.coord(n, 0), dy = x(1) - mesh.coord(n, 1);
  const double ax = 1.0 - std::abs(dx) / mesh.h(0), ay = 1.0 - std::abs(dy) / mesh.h(1);
  if (ax <= 0 || ay <= 0) return Vector2d::Zero();
  const double sx = (dx > 0 ? -1.0 : 1.0) / mesh.h(0), sy = (dy > 0 ? -1.0 : 1.0) / mesh.h(1);
  return Vector2d(sx * ay, ax * sy);
}
Eigen::Vector4d cornerValues(const Mesh& mesh, int n, const Corners& x) {
  Eigen::Vector4d Sc;
  for (int c = 0; c < 4; ++c) Sc(c) = hat(mesh, n, x.col(c));
  return Sc;
}

// domain averages over the quadrilateral x of the isoparametric interpolant of
// corner values Sc and of its gradient; also the area and the centroid
struct QuadAverages {
  double V = 0;                          // area
  Vector2d centroid = Vector2d::Zero();  // (1/V) int x dA
  double S = 0;                          // (1/V) int S^ dA
  Vector2d dS = Vector2d::Zero();        // (1/V) int grad S^ dA
  Eigen::Vector4d w = Eigen::Vector4d::Zero();  // (1/V) int N_c dA
};
QuadAverages gaussAverages(const Corners& x, const Eigen::Vector4d& Sc) {
  const double g[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, gw[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  QuadAverages a;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double r = g[i], s = g[j], wq = gw[i] * gw[j];
      Eigen::Vector4d N;
      Eigen::Matrix<double, 2, 4> dN;  // d N_c / d(xi, eta)
      for (int c = 0; c < 4; ++c) {
        N(c) = 0.25 * (1 + xiC[c] * r) * (1 + etaC[c] * s);
        dN(0, c) = 0.25 * xiC[c] * (1 + etaC[c] * s);
        dN(1, c) = 0.25 * etaC[c] * (1 + xiC[c] * r);
      }
      const Eigen::Matrix2d J = x * dN.transpose();  // columns dx/dxi, dx/deta
      const double detJ = J.determinant();
      const Vector2d gradS = J.inverse().transpose() * (dN * Sc);
      a.V += wq * detJ;
      a.centroid += wq * detJ * (x * N);
      a.S += wq * detJ * N.dot(Sc);
      a.dS += wq * detJ * gradS;
      a.w += wq * detJ * N;
    }
  a.centroid /= a.V;
  a.S /= a.V;
  a.dS /= a.V;
  a.w /= a.V;
  return a;
}

// sums over all grid nodes of a basis (S, dS) evaluated by `basis(node)`
struct Sums {
  double S = 0;
  Vector2d dS = Vector2d::Zero(), x = Vector2d::Zero();
  Eigen::Matrix2d gradX = Eigen::Matrix2d::Zero();  // sum X_v (x) dS_v
};
template <class Basis>
Sums sumOverNodes(const Mesh& mesh, Basis basis) {
  Sums s;
  for (int n = 0; n < mesh.nodes(); ++n) {
    const Basis2D b = basis(n);
    const Vector2d Xn = mesh.coord.row(n).transpose();
    s.S += b.S;
    s.dS += b.dS;
    s.x += b.S * Xn;
    s.gradX += Xn * b.dS.transpose();
  }
  return s;
}

Corners parallelogram(const Vector2d& c, const Eigen::Matrix2d& st) {
  Corners x;
  for (int k = 0; k < 4; ++k) x.col(k) = c + 0.5 * (xiC[k] * st.col(0) + etaC[k] * st.col(1));
  return x;
}

// a 4 x 4 grid with unequal spacing h = (1, 0.8)
Mesh grid() { return formCoord2D(4, 4, 4.0, 3.2); }

// distorted (non-parallelogram), convex, anticlockwise quadrilateral over four cells
Corners distortedQuad() {
  Corners x;
  x << 1.30, 2.55, 2.40, 1.15,  //
      1.00, 0.85, 2.10, 1.75;
  return x;
}
}  // namespace

TEST_SUITE("SvpCPDI2") {
  TEST_CASE("SvpCPDI2: the test quadrilateral is anticlockwise and not a parallelogram") {
    const Corners x = distortedQuad();
    CHECK(quadArea(x) > 0.0);
    CHECK((x.col(0) + x.col(2) - x.col(1) - x.col(3)).norm() > 0.1);
    CHECK(std::abs(quadArea(x) - gaussAverages(x, Eigen::Vector4d::Zero()).V) <= 1e-13);
  }

  TEST_CASE("SvpCPDI2: partition of unity on a distorted quadrilateral") {
    const Mesh mesh = grid();
    const Corners x = distortedQuad();
    const Sums s = sumOverNodes(mesh, [&](int n) { return SvpCPDI2(cornerValues(mesh, n, x), x); });
    CHECK(std::abs(s.S - 1.0) <= 1e-13);
    CHECK(s.dS.norm() <= 1e-13);
  }

  TEST_CASE("SvpCPDI2: linear reproduction (centroid of the bilinear quad / sum X (x) dS = I)") {
    const Mesh mesh = grid();
    const Corners x = distortedQuad();
    const Sums s = sumOverNodes(mesh, [&](int n) { return SvpCPDI2(cornerValues(mesh, n, x), x); });
    const Vector2d centroid = gaussAverages(x, Eigen::Vector4d::Zero()).centroid;
    CHECK((centroid - x.rowwise().mean()).norm() > 1e-3);  // not the corner mean
    CHECK((s.x - centroid).norm() <= 1e-13);
    CHECK((s.gradX - Eigen::Matrix2d::Identity()).norm() <= 1e-12);
  }

  TEST_CASE("SvpCPDI2: value is the domain average of the bilinear interpolant of arbitrary corner values") {
    const Corners x = distortedQuad();
    const Eigen::Vector4d cases[3] = {Eigen::Vector4d(0.3, -1.2, 2.5, 0.7),
                                      Eigen::Vector4d(1.0, 0.0, 0.0, 0.0),
                                      Eigen::Vector4d(-0.4, 0.9, 0.1, 3.3)};
    for (const Eigen::Vector4d& Sc : cases) {
      CAPTURE(Sc.transpose());
      const QuadAverages a = gaussAverages(x, Sc);
      CHECK(std::abs(SvpCPDI2(Sc, x).S - a.S) <= 1e-13);
    }
  }

  TEST_CASE("SvpCPDI2: cpdi2Weights equal (1/V) int N_c dA and sum to one") {
    Corners x2 = distortedQuad();
    x2.col(2) += Vector2d(0.4, 0.3);  // a second, more distorted shape
    for (const Corners& x : {distortedQuad(), x2}) {
      const Eigen::Vector4d w = cpdi2Weights(x);
      const QuadAverages a = gaussAverages(x, Eigen::Vector4d::Zero());
      CHECK((w - a.w).norm() <= 1e-13);
      CHECK(std::abs(w.sum() - 1.0) <= 1e-14);
      CHECK((w.array() - 0.25).abs().maxCoeff() > 1e-3);  // not the CPDI1 weights
    }
  }

  TEST_CASE("SvpCPDI2: gradient is the domain average of the gradient of the bilinear interpolant") {
    const Corners x = distortedQuad();
    const Eigen::Vector4d cases[3] = {Eigen::Vector4d(0.3, -1.2, 2.5, 0.7),
                                      Eigen::Vector4d(0.0, 1.0, 0.0, 0.0),
                                      Eigen::Vector4d(-0.4, 0.9, 0.1, 3.3)};
    for (const Eigen::Vector4d& Sc : cases) {
      CAPTURE(Sc.transpose());
      const QuadAverages a = gaussAverages(x, Sc);
      CHECK((SvpCPDI2(Sc, x).dS - a.dS).norm() <= 1e-12);
    }
  }

  TEST_CASE("SvpCPDI2: translating a parallelogram inside one cell / FD of S equals the gradient") {
    // inside one cell the grid basis is bilinear; for a parallelogram the
    // bilinear interpolant of the corner values equals the hat function itself,
    // so d S / d(translation) is the average gradient
    const Mesh mesh = grid();  // cell [1,2] x [0.8,1.6]
    Eigen::Matrix2d st;
    st << 0.30, -0.10,  //
        0.08, 0.25;
    const Corners x = parallelogram(Vector2d(1.45, 1.2), st);
    const double d = 1e-6;
    for (int n : {6, 7, 11, 12}) {  // the nodes of that cell
      CAPTURE(n);
      const Basis2D b = SvpCPDI2(cornerValues(mesh, n, x), x);
      const Basis2D b1 = SvpCPDI1(cornerValues(mesh, n, x), st);
      for (int i = 0; i < 2; ++i) {
        Corners xp = x, xm = x;
        xp.row(i).array() += d;
        xm.row(i).array() -= d;
        const double fd2 = (SvpCPDI2(cornerValues(mesh, n, xp), xp).S -
                            SvpCPDI2(cornerValues(mesh, n, xm), xm).S) / (2 * d);
        const double fd1 = (SvpCPDI1(cornerValues(mesh, n, xp), st).S -
                            SvpCPDI1(cornerValues(mesh, n, xm), st).S) / (2 * d);
        CHECK(std::abs(fd2 - b.dS(i)) <= 1e-7);
        CHECK(std::abs(fd1 - b1.dS(i)) <= 1e-7);
      }
    }
  }

  TEST_CASE("SvpCPDI2: translating a distorted quad inside one cell / FD of S = gradient + analytic edge term") {
    // For a non-parallelogram the bilinear interpolant S^ of the corner values
    // differs from the hat function N = a + bx + cy + dxy along the edges, so the
    // translation derivative sum_c w_c grad N(x_c) = grad N(centroid) differs
    // from the CPDI2 gradient (1/V) oint S^ n ds by minus
    //   (d/(6V)) sum_edges (dx dy^2, -dx^2 dy),  d = d2N/dxdy.
    const Mesh mesh = grid();
    Corners x;
    x << 1.15, 1.80, 1.70, 1.25,  //
        0.90, 0.95, 1.50, 1.35;
    REQUIRE(quadArea(x) > 0);
    const double V = quadArea(x), d = 1e-6;
    Vector2d edge = Vector2d::Zero();
    for (int c = 0; c < 4; ++c) {
      const Vector2d e = x.col((c + 1) % 4) - x.col(c);
      edge += Vector2d(e(0) * e(1) * e(1), -e(0) * e(0) * e(1));
    }
    REQUIRE(edge.norm() > 1e-3);  // a genuinely distorted shape
    const Vector2d centroid = gaussAverages(x, Eigen::Vector4d::Zero()).centroid;
    for (int n : {6, 7, 11, 12}) {
      CAPTURE(n);
      const double dxy = ((n == 6 || n == 12) ? 1.0 : -1.0) / (mesh.h(0) * mesh.h(1));
      const Basis2D b = SvpCPDI2(cornerValues(mesh, n, x), x);
      CHECK((b.dS - dxy / (6 * V) * edge - hatGrad(mesh, n, centroid)).norm() <= 1e-12);
      for (int i = 0; i < 2; ++i) {
        Corners xp = x, xm = x;
        xp.row(i).array() += d;
        xm.row(i).array() -= d;
        const double fd = (SvpCPDI2(cornerValues(mesh, n, xp), xp).S -
                           SvpCPDI2(cornerValues(mesh, n, xm), xm).S) / (2 * d);
        CHECK(std::abs(fd - (b.dS(i) - dxy / (6 * V) * edge(i))) <= 1e-7);
      }
    }
  }

  TEST_CASE("SvpCPDI2: cpdi2Weights of a trapezoid by hand / unchanged by translation / rotation / scaling") {
    // symmetric trapezoid, bottom width a = 2, top b = 1, height H: det J = (H/8)((a+b) + (b-a) eta),
    // J1 = 0, so w_c = 1/4 + eta_c (b-a) / (12 (a+b)) = 1/4 -+ 1/36: bottom corners 5/18, top 2/9
    Corners trap;
    trap << 0.0, 2.0, 1.5, 0.5,  //
        0.0, 0.0, 0.7, 0.7;
    const Eigen::Vector4d wTrap(5.0 / 18, 5.0 / 18, 2.0 / 9, 2.0 / 9);
    // the same trapezoid turned by 90 degrees, corners in the same order: the same weights
    Corners side;
    side << 0.0, 0.0, -0.7, -0.7,  //
        0.0, 2.0, 1.5, 0.5;
    // rotating the corner list (corner 1 first) rotates the weights
    Corners shifted;
    shifted << 2.0, 1.5, 0.5, 0.0,  //
        0.0, 0.7, 0.7, 0.0;
    const Eigen::Vector4d wShifted(5.0 / 18, 2.0 / 9, 2.0 / 9, 5.0 / 18);
    const Corners q = distortedQuad();
    const Eigen::Vector4d wq = gaussAverages(q, Eigen::Vector4d::Zero()).w;
    const double ang = 0.61, c = std::cos(ang), sn = std::sin(ang);
    Eigen::Matrix2d R;
    R << c, -sn, sn, c;
    for (int rep = 0; rep < 2; ++rep) {
      CHECK((cpdi2Weights(trap) - wTrap).norm() <= 1e-14);
      CHECK((cpdi2Weights(side) - wTrap).norm() <= 1e-14);
      CHECK((cpdi2Weights(shifted) - wShifted).norm() <= 1e-14);
      for (double scale : {1.0, 3.7, 2e-3}) {  // the distorted quad moved, turned and scaled
        CAPTURE(scale);
        const Corners moved = ((scale * R * q).colwise() + Vector2d(12.5, -7.25));
        CHECK((cpdi2Weights(moved) - wq).norm() <= 1e-12);
        CHECK((cpdi2Weights(scale * trap) - wTrap).norm() <= 1e-13);
      }
    }
  }

  TEST_CASE("SvpCPDI2: value equals the domain average for quadrilaterals of different shapes in turn") {
    // a kite, a trapezoid and a strongly distorted convex quad; corner values chosen freely
    Corners kite, trap, q3;
    kite << 0.0, 1.0, 0.0, -1.0,  //
        -0.5, 0.0, 2.0, 0.0;
    trap << 0.0, 2.0, 1.5, 0.5,  //
        0.0, 0.0, 0.7, 0.7;
    q3 << 0.1, 3.0, 2.2, -0.4,  //
        0.2, 0.6, 1.9, 1.1;
    const Eigen::Vector4d Sc(0.3, -1.2, 2.5, 0.7);
    for (int rep = 0; rep < 2; ++rep)
      for (const Corners& x : {kite, trap, q3}) {
        CAPTURE(x);
        REQUIRE(quadArea(x) > 0);
        const QuadAverages a = gaussAverages(x, Sc);
        CHECK(std::abs(SvpCPDI2(Sc, x).S - a.S) <= 1e-13);
        CHECK((cpdi2Weights(x) - gaussAverages(x, Eigen::Vector4d::Zero()).w).norm() <= 1e-13);
        CHECK(std::abs(cpdi2Weights(x).sum() - 1.0) <= 1e-14);
      }
  }
}

TEST_SUITE("SvpCPDI1") {
  Eigen::Matrix2d generalST() {  // s, t not axis-aligned, anticlockwise
    Eigen::Matrix2d st;
    st << 0.60, -0.25,  //
        0.20, 0.70;
    return st;
  }

  TEST_CASE("SvpCPDI1: partition of unity and linear reproduction on a general parallelogram") {
    const Mesh mesh = grid();
    const Eigen::Matrix2d st = generalST();
    const Vector2d c(2.1, 1.5);
    const Corners x = parallelogram(c, st);
    const Sums s = sumOverNodes(mesh, [&](int n) { return SvpCPDI1(cornerValues(mesh, n, x), st); });
    CHECK(std::abs(s.S - 1.0) <= 1e-13);
    CHECK(s.dS.norm() <= 1e-13);
    CHECK((s.x - c).norm() <= 1e-13);
    CHECK((s.gradX - Eigen::Matrix2d::Identity()).norm() <= 1e-12);
  }

  TEST_CASE("SvpCPDI1: value and gradient are domain averages of the bilinear interpolant (parallelogram)") {
    const Eigen::Matrix2d st = generalST();
    const Corners x = parallelogram(Vector2d(2.1, 1.5), st);
    for (const Eigen::Vector4d& Sc : {Eigen::Vector4d(0.3, -1.2, 2.5, 0.7), Eigen::Vector4d(0, 0, 1, 0)}) {
      CAPTURE(Sc.transpose());
      const QuadAverages a = gaussAverages(x, Sc);
      const Basis2D b = SvpCPDI1(Sc, st);
      CHECK(std::abs(b.S - a.S) <= 1e-13);
      CHECK((b.dS - a.dS).norm() <= 1e-12);
    }
  }

  TEST_CASE("SvpCPDI1: equals CPDI2 for a rectangle and for a general parallelogram") {
    Eigen::Matrix2d rect;
    rect << 0.7, 0.0,  //
        0.0, 0.45;
    const Mesh mesh = grid();
    for (const Eigen::Matrix2d& st : {rect, generalST()}) {
      const Corners x = parallelogram(Vector2d(2.05, 1.55), st);
      for (int n = 0; n < mesh.nodes(); ++n) {
        CAPTURE(n);
        const Eigen::Vector4d Sc = cornerValues(mesh, n, x);
        const Basis2D b1 = SvpCPDI1(Sc, st), b2 = SvpCPDI2(Sc, x);
        CHECK(std::abs(b1.S - b2.S) <= 1e-14);
        CHECK((b1.dS - b2.dS).norm() <= 1e-13);
      }
    }
  }

  TEST_CASE("SvpCPDI1: rectangle gradient against the analytic average of the hat gradient") {
    // an axis-aligned rectangle inside one cell: the average of grad N of a
    // bilinear N equals grad N at the centre
    const Mesh mesh = grid();
    Eigen::Matrix2d st;
    st << 0.3, 0.0,  //
        0.0, 0.2;
    const Vector2d c(1.4, 1.1);
    const Corners x = parallelogram(c, st);
    for (int n : {6, 7, 11, 12}) {
      const Basis2D b = SvpCPDI1(cornerValues(mesh, n, x), st);
      CHECK(std::abs(b.S - hat(mesh, n, c)) <= 1e-14);
      CHECK((b.dS - hatGrad(mesh, n, c)).norm() <= 1e-13);
    }
  }
}

TEST_SUITE("SvpCPDI2") {
  TEST_CASE("SvpCPDI2: CPDI1 and CPDI2 points through elemMPinfoCPDI reproduce linear fields") {
    Mesh mesh = grid();
    std::vector<MaterialPoint> mpData(2);
    MaterialPoint& p1 = mpData[0];  // CPDI1: general parallelogram
    p1.mpType = MpType::CPDI1;
    p1.cpdi = CpdiDomain();
    p1.mpC = Vector2d(2.1, 1.5);
    p1.cpdi->st << 0.60, -0.25, 0.20, 0.70;
    p1.cpdi->st0 = p1.cpdi->st;
    MaterialPoint& p2 = mpData[1];  // CPDI2: distorted quadrilateral
    p2.mpType = MpType::CPDI2;
    p2.cpdi = CpdiDomain();
    p2.cpdi->xc = distortedQuad();
    p2.mpC = gaussAverages(p2.cpdi->xc, Eigen::Vector4d::Zero()).centroid;
    elemMPinfoCPDI(mesh, mpData);

    const Corners xs[2] = {parallelogram(p1.mpC, p1.cpdi->st), p2.cpdi->xc};
    for (int p = 0; p < 2; ++p) {
      const MaterialPoint& mp = mpData[p];
      CAPTURE(p);
      REQUIRE(mp.nn > 4);  // the domain spans several cells
      // every node whose hat function is non-zero at a corner is linked
      for (int n = 0; n < mesh.nodes(); ++n)
        if (cornerValues(mesh, n, xs[p]).maxCoeff() > 0.0)
          CHECK(std::find(mp.nIN.begin(), mp.nIN.begin() + mp.nn, n) != mp.nIN.begin() + mp.nn);
      double S = 0;
      Vector2d dS = Vector2d::Zero(), x = Vector2d::Zero();
      Eigen::Matrix2d gradX = Eigen::Matrix2d::Zero();
      for (int v = 0; v < mp.nn; ++v) {
        const Vector2d Xv = mesh.coord.row(mp.nIN[v]).transpose();
        S += mp.Svp[v];
        dS += mp.dSvp.col(v);
        x += mp.Svp[v] * Xv;
        gradX += Xv * mp.dSvp.col(v).transpose();
      }
      CHECK(std::abs(S - 1.0) <= 1e-13);
      CHECK(dS.norm() <= 1e-13);
      CHECK((x - mp.mpC).norm() <= 1e-13);  // centre / centroid of the domain
      CHECK((gradX - Eigen::Matrix2d::Identity()).norm() <= 1e-12);
    }
  }
}
