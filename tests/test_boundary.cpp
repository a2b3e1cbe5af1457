// Tests of the implicit boundaries of [Boundaries]: the boundary
// data (ample/boundaries/boundary.h), the Dirichlet function of eq 16 and its band integrals
// (dirichletBand), the cut cells (cutCells), the polygon clip (clipPolygon) and the
// point generation of sec 4 (fillPolygon, addBoundary, solidPolygon in setupHelpers).
// Every value is by hand (worked out in the comments) or an invariant.
#include "ample/boundaries/boundary.h"
#include "ample/meshes/clipPolygon.h"
#include "ample/boundaries/cutCells.h"
#include "ample/boundaries/dirichletBand.h"
#include "ample/errors.h"
#include "setups/formCoord2D.h"
#include "setups/setupHelpers.h"
#include "setups/setups.h"
#include <doctest/doctest.h>
#include <cmath>
#include <functional>

using namespace ample;

namespace {
bool near(double a, double b, double tol) { return std::abs(a - b) <= tol; }

// fine trapezoidal rule of f over [0, delta]
double trapezoid(const std::function<double(double)>& f, double delta, int N) {
  const double dx = delta / N;
  double sum = 0.5 * (f(0.0) + f(delta));
  for (int i = 1; i < N; ++i) sum += f(i * dx);
  return sum * dx;
}

Common pointParams(int mp, int mpType = 2) {
  Common p;
  p.mp = mp;
  p.mpType = MpType(mpType);
  p.E = 1e6;
  p.nu = 0.3;
  return p;
}

double totalVolume(const std::vector<MaterialPoint>& mpData) {
  double V = 0;
  for (const MaterialPoint& p : mpData) V += p.vp0;
  return V;
}

void checkCut(const CutCell& c, int seg, int cell, double r0, double r1) {
  CHECK(c.seg == seg);
  CHECK(c.cell == cell);
  CHECK(near(c.r0, r0, 1e-14));
  CHECK(near(c.r1, r1, 1e-14));
}
}  // namespace

TEST_SUITE("boundary") {
  TEST_CASE("boundary: inward normal and tangent and signed distance on both sides") {
    Boundary b;
    b.x = {{0, 0}, {2, 0}};
    b.type = {BoundaryType::Roller};
    // solid on the left of (0,0) -> (2,0): above, n = (0, 1), t = n turned +90 deg = (-1, 0)
    CHECK(near((inwardNormal(b, 0) - Vector2d(0, 1)).norm(), 0, 1e-15));
    CHECK(near((tangent(b, 0) - Vector2d(-1, 0)).norm(), 0, 1e-15));
    CHECK(near(signedDistance(b, 0, Vector2d(0.5, 0.2)), 0.2, 1e-15));
    CHECK(near(signedDistance(b, 0, Vector2d(0.5, -0.3)), -0.3, 1e-15));
    b.solid = SolidSide::Right;  // solid below
    CHECK(near((inwardNormal(b, 0) - Vector2d(0, -1)).norm(), 0, 1e-15));
    CHECK(near(signedDistance(b, 0, Vector2d(0.5, -0.3)), 0.3, 1e-15));
    // 30 degrees: (0,0) -> (cos 30, sin 30), n = (-sin 30, cos 30)
    b.x = {{0, 0}, {std::sqrt(3.0) / 2, 0.5}};
    b.solid = SolidSide::Left;
    CHECK(near((inwardNormal(b, 0) - Vector2d(-0.5, std::sqrt(3.0) / 2)).norm(), 0, 1e-15));
    CHECK(near((pointAt(b, 0, 0.5) - Vector2d(std::sqrt(3.0) / 4, 0.25)).norm(), 0, 1e-15));
  }

  TEST_CASE("boundary: duAt gives the step's increment and the last one after it") {
    Boundary b;
    CHECK(duAt(b, 3) == Vector2d::Zero());
    b.du = {{0, -1}, {0, -2}};
    CHECK(duAt(b, 1) == Vector2d(0, -1));
    CHECK(duAt(b, 2) == Vector2d(0, -2));
    CHECK(duAt(b, 7) == Vector2d(0, -2));
  }
}

TEST_SUITE("dirichletBand") {
  TEST_CASE("dirichletBand: eq 16 value and slope at hand-picked distances") {
    const double delta = 0.5;  // d = 1 - (1 - phi/delta)^2, d' = (2/delta)(1 - phi/delta)
    struct Row { double phi, d, dp; };
    const Row rows[] = {
        {-0.1, 0.0, 0.0},       // outside the solid
        {0.0, 0.0, 4.0},        // on the boundary: d = 0, slope 2/delta
        {0.125, 0.4375, 3.0},   // phi/delta = 1/4: 1 - 9/16, 4 * 3/4
        {0.25, 0.75, 2.0},      // phi/delta = 1/2: 1 - 1/4, 4 * 1/2
        {0.5, 1.0, 0.0},        // phi = delta: 1, slope 0 (C1 there)
        {0.7, 1.0, 0.0},        // inside, beyond the band
    };
    for (const Row& r : rows) {
      CAPTURE(r.phi);
      CHECK(near(dirichletD(r.phi, delta), r.d, 1e-15));
      CHECK(near(dirichletDPrime(r.phi, delta), r.dp, 1e-14));
    }
    // the default band of [Boundaries]: delta = 1e-6 h, h = 10 mm; half way: d = 3/4, d' = 1/delta
    const double dh = 1e-6 * 0.01;
    CHECK(near(dirichletD(0.5 * dh, dh), 0.75, 1e-12));
    CHECK(near(dirichletDPrime(0.5 * dh, dh) * dh, 1.0, 1e-12));
    // grad d = d' n: n = (0.6, 0.8) at phi = delta/2 -> 2 (0.6, 0.8)
    CHECK(near((dirichletGrad(0.25, delta, Vector2d(0.6, 0.8)) - Vector2d(1.2, 1.6)).norm(), 0,
               1e-14));
  }

  TEST_CASE("dirichletBand: d = s (2 - s) and d' = 2 (1 - s) / delta for band widths 0.5 / 2 / 1e-3 / 3e-8 in turn") {
    // s = phi/delta; d and d' continuous at phi = 0 and phi = delta (d = 0, 1; d' = 2/delta, 0
    // inside the band, 0 outside it); d' against central differences of d; 0 <= d <= 1, rising
    const double s[6] = {0.0, 0.1, 0.25, 0.5, 0.8, 1.0};
    for (int rep = 0; rep < 2; ++rep)
      for (double delta : {0.5, 2.0, 1e-3, 3e-8}) {
        CAPTURE(delta);
        for (double sk : s) {
          CAPTURE(sk);
          CHECK(near(dirichletD(sk * delta, delta), sk * (2 - sk), 1e-15));
          CHECK(near(dirichletDPrime(sk * delta, delta) * delta, 2 * (1 - sk), 1e-14));
        }
        for (double f : {-0.3, -1e-3, -5.0}) {  // outside the solid
          CHECK(dirichletD(f * delta, delta) == 0.0);
          CHECK(dirichletDPrime(f * delta, delta) == 0.0);
        }
        for (double f : {1.2, 1.001, 5.0}) {  // beyond the band
          CHECK(dirichletD(f * delta, delta) == 1.0);
          CHECK(dirichletDPrime(f * delta, delta) == 0.0);
        }
        const double e = 1e-9 * delta;  // across phi = 0 (d' jumps to 2/delta) and phi = delta
        CHECK(near(dirichletD(-e, delta), dirichletD(e, delta), 1e-8));
        CHECK(near(dirichletDPrime(e, delta) * delta, 2.0, 1e-8));
        CHECK(near(dirichletD(delta - e, delta), dirichletD(delta + e, delta), 1e-8));
        CHECK(near(dirichletDPrime(delta - e, delta) * delta, dirichletDPrime(delta + e, delta) * delta, 1e-8));
        double prev = -1.0;
        for (int k = 1; k < 50; ++k) {
          const double phi = (k / 50.0) * delta, step = 1e-6 * delta;
          const double d = dirichletD(phi, delta);
          CHECK(d >= 0.0);
          CHECK(d <= 1.0);
          CHECK(d > prev);
          prev = d;
          const double fd = (dirichletD(phi + step, delta) - dirichletD(phi - step, delta)) / (2 * step);
          CHECK(near(fd * delta, dirichletDPrime(phi, delta) * delta, 1e-7));
        }
      }
  }

  TEST_CASE("dirichletBand: band integrals by hand and by a fine trapezoidal rule") {
    for (double delta : {0.5, 1e-8}) {
      CAPTURE(delta);
      const BandIntegrals I = bandIntegrals(delta);
      // by hand with s = phi/delta: int d' = 1, int d d' = 1/2, int d'^2 = 4/(3 delta),
      // int d = 2 delta/3, int d^2 = delta (1 - 2/3 + 1/5) = 8 delta/15
      CHECK(near(I.dp, 1.0, 1e-15));
      CHECK(near(I.d_dp, 0.5, 1e-15));
      CHECK(near(I.dp_dp * delta, 4.0 / 3.0, 1e-14));
      CHECK(near(I.d / delta, 2.0 / 3.0, 1e-14));
      CHECK(near(I.d_d / delta, 8.0 / 15.0, 1e-14));
      // trapezoidal rule, N = 20000: error ~ delta^3 max|f''| / (12 N^2), relative < 1e-8
      const int N = 20000;
      auto d = [&](double p) { return dirichletD(p, delta); };
      auto dp = [&](double p) { return dirichletDPrime(p, delta); };
      const double tol = 1e-8;
      CHECK(near(trapezoid(dp, delta, N), I.dp, tol));
      CHECK(near(trapezoid([&](double p) { return d(p) * dp(p); }, delta, N), I.d_dp, tol));
      CHECK(near(trapezoid([&](double p) { return dp(p) * dp(p); }, delta, N) * delta,
                 I.dp_dp * delta, tol));
      CHECK(near(trapezoid(d, delta, N) / delta, I.d / delta, tol));
      CHECK(near(trapezoid([&](double p) { return d(p) * d(p); }, delta, N) / delta,
                 I.d_d / delta, tol));
    }
  }
}

TEST_SUITE("cutCells") {
  TEST_CASE("cutCells: a 45 degree segment across a 3 x 3 grid") {
    const Mesh mesh = formCoord2D(3, 3, 3.0, 3.0);  // h = 1, cells numbered x fastest
    Boundary b;
    b.x = {{0.25, 0.5}, {2.25, 2.5}};  // y = x + 1/4, x = 0.25 + 2 r
    b.type = {BoundaryType::Fixed};
    // crossings: y = 1 at x = 0.75 (r = 1/4), x = 1 at y = 1.25 (r = 3/8),
    //            y = 2 at x = 1.75 (r = 3/4), x = 2 at y = 2.25 (r = 7/8)
    const std::vector<CutCell> cut = cutCells(mesh, b);
    REQUIRE(cut.size() == 5);
    checkCut(cut[0], 0, 0, 0.0, 0.25);    // cell (0, 0)
    checkCut(cut[1], 0, 3, 0.25, 0.375);  // cell (0, 1)
    checkCut(cut[2], 0, 4, 0.375, 0.75);  // cell (1, 1)
    checkCut(cut[3], 0, 7, 0.75, 0.875);  // cell (1, 2)
    checkCut(cut[4], 0, 8, 0.875, 1.0);   // cell (2, 2)
  }

  TEST_CASE("cutCells: a 30 degree segment across a 3 x 3 grid") {
    const Mesh mesh = formCoord2D(3, 3, 3.0, 3.0);
    Boundary b;
    const double t30 = 1.0 / std::sqrt(3.0);
    b.x = {{0, 0.25}, {3, 0.25 + 3 * t30}};  // y = 0.25 + x tan 30, x = 3 r
    b.type = {BoundaryType::Roller};
    // x = 1 at y = 0.827 (r = 1/3); y = 1 at x = 0.75 sqrt 3 (r = sqrt(3)/4);
    // x = 2 at y = 1.405 (r = 2/3); ends at y = 1.982, in the second row
    const std::vector<CutCell> cut = cutCells(mesh, b);
    REQUIRE(cut.size() == 4);
    const double rY1 = std::sqrt(3.0) / 4.0;
    checkCut(cut[0], 0, 0, 0.0, 1.0 / 3.0);   // cell (0, 0)
    checkCut(cut[1], 0, 1, 1.0 / 3.0, rY1);   // cell (1, 0)
    checkCut(cut[2], 0, 4, rY1, 2.0 / 3.0);   // cell (1, 1)
    checkCut(cut[3], 0, 5, 2.0 / 3.0, 1.0);   // cell (2, 1)
  }

  TEST_CASE("cutCells: a diagonal through the nodes cuts only the cells it crosses") {
    const Mesh mesh = formCoord2D(3, 3, 3.0, 3.0);
    Boundary b;
    b.x = {{0, 0}, {3, 3}};  // through the nodes (1,1) and (2,2): cells touched at a node give nothing
    b.type = {BoundaryType::Fixed};
    const std::vector<CutCell> cut = cutCells(mesh, b);
    REQUIRE(cut.size() == 3);
    checkCut(cut[0], 0, 0, 0.0, 1.0 / 3.0);
    checkCut(cut[1], 0, 4, 1.0 / 3.0, 2.0 / 3.0);
    checkCut(cut[2], 0, 8, 2.0 / 3.0, 1.0);
  }

  TEST_CASE("cutCells: a segment on a grid line belongs to the cell on the solid side") {
    const Mesh mesh = formCoord2D(2, 2, 2.0, 2.0);
    Boundary b;
    b.x = {{1, 0}, {1, 2}};  // on x = 1, upwards
    b.type = {BoundaryType::Roller};
    std::vector<CutCell> cut = cutCells(mesh, b);  // solid left: x < 1, cells 0 and 2
    REQUIRE(cut.size() == 2);
    checkCut(cut[0], 0, 0, 0.0, 0.5);
    checkCut(cut[1], 0, 2, 0.5, 1.0);
    b.solid = SolidSide::Right;  // x > 1: cells 1 and 3
    cut = cutCells(mesh, b);
    REQUIRE(cut.size() == 2);
    checkCut(cut[0], 0, 1, 0.0, 0.5);
    checkCut(cut[1], 0, 3, 0.5, 1.0);
    b.x = {{0, 0}, {0, 2}};  // the grid's left edge with the solid to its left: outside the grid
    b.solid = SolidSide::Left;
    CHECK(cutCells(mesh, b).empty());
  }

  TEST_CASE("cutCells: two segments of a polyline are listed in order") {
    const Mesh mesh = formCoord2D(2, 2, 2.0, 2.0);
    Boundary b;
    b.x = {{0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}};  // right along y = 0.5, then up x = 1.5
    b.type = {BoundaryType::Fixed, BoundaryType::Roller};
    const std::vector<CutCell> cut = cutCells(mesh, b);
    REQUIRE(cut.size() == 4);
    checkCut(cut[0], 0, 0, 0.0, 0.5);
    checkCut(cut[1], 0, 1, 0.5, 1.0);
    checkCut(cut[2], 1, 1, 0.0, 0.5);
    checkCut(cut[3], 1, 3, 0.5, 1.0);
  }
}

TEST_SUITE("clipPolygon") {
  TEST_CASE("clipPolygon: a square cut by a non-convex solid in two pieces") {
    // solid: the square [0,2]^2 with a notch x in [1.1, 1.3] from the top down to y = 0.7
    const Polygon solid = {{0, 0}, {2, 0}, {2, 2}, {1.3, 2}, {1.3, 0.7}, {1.1, 0.7}, {1.1, 2}, {0, 2}};
    // window [1,2] x [1,2]: two pieces, [1,1.1] x [1,2] (0.1) and [1.3,2] x [1,2] (0.7)
    const Polygon top = {{1, 1}, {2, 1}, {2, 2}, {1, 2}};
    const AreaCentroid a = polygonArea(clipPolygon(solid, top));
    CHECK(near(a.area, 0.8, 1e-14));
    CHECK(near(a.centroid(0), (0.1 * 1.05 + 0.7 * 1.65) / 0.8, 1e-14));  // 1.575
    CHECK(near(a.centroid(1), 1.5, 1e-14));
    // window [1,2] x [0,1]: the notch takes 0.2 x 0.3 centred at (1.2, 0.85)
    const Polygon bottom = {{1, 0}, {2, 0}, {2, 1}, {1, 1}};
    const AreaCentroid c = polygonArea(clipPolygon(solid, bottom));
    CHECK(near(c.area, 0.94, 1e-14));
    CHECK(near(c.centroid(0), (1.5 - 0.06 * 1.2) / 0.94, 1e-14));
    CHECK(near(c.centroid(1), (0.5 - 0.06 * 0.85) / 0.94, 1e-14));
    // a window wholly outside: nothing
    const Polygon away = {{3, 3}, {4, 3}, {4, 4}, {3, 4}};
    CHECK(clipPolygon(solid, away).empty());
  }
}

TEST_SUITE("fillPolygon") {
  TEST_CASE("fillPolygon: a block on grid lines gives exactly fillBlock's points") {
    const Mesh mesh = formCoord2D(4, 3, 4.0, 3.0);
    for (int mpType : {1, 2, 4}) {
      CAPTURE(mpType);
      const Common P = pointParams(2, mpType);
      std::vector<MaterialPoint> ref, pts, cw;
      fillBlock(ref, Vector2d(1, 1), 2, 1, mesh.h, P, 1000.0);  // cells [1,3] x [1,2]
      fillPolygon(pts, Vector2d::Zero(), 4, 3, mesh.h, P, 1000.0, {{1, 1}, {3, 1}, {3, 2}, {1, 2}});
      fillPolygon(cw, Vector2d::Zero(), 4, 3, mesh.h, P, 1000.0, {{1, 1}, {1, 2}, {3, 2}, {3, 1}});
      REQUIRE(pts.size() == ref.size());
      REQUIRE(cw.size() == ref.size());
      for (size_t i = 0; i < ref.size(); ++i)
        for (const MaterialPoint* p : {&pts[i], &cw[i]}) {
          CAPTURE(i);
          CHECK(p->mpType == ref[i].mpType);
          CHECK(p->mpC == ref[i].mpC);  // bit for bit
          CHECK(p->X0 == ref[i].X0);
          CHECK(p->vp0 == ref[i].vp0);
          CHECK(p->vp == ref[i].vp);
          CHECK(p->mpM == ref[i].mpM);
          CHECK(p->lp0 == ref[i].lp0);
          CHECK(p->lp == ref[i].lp);
          REQUIRE(bool(p->cpdi) == (mpType == 4));    // a domain for the CPDI points only
          if (p->cpdi) CHECK(p->cpdi->st0 == ref[i].cpdi->st0);
          if (p->cpdi) CHECK(p->cpdi->xc == ref[i].cpdi->xc);
          CHECK((p->mCst.E == ref[i].mCst.E && p->mCst.nu == ref[i].mCst.nu && p->mCst.rhoY == ref[i].mCst.rhoY));
        }
    }
  }

  TEST_CASE("fillPolygon: the lower-left half of a 2 x 2 grid") {
    // mp = 2: squares of side 1/2, [i/2, (i+1)/2] x [j/2, (j+1)/2]; the diagonal x + y = 2
    // keeps i + j <= 2 whole (6), halves i + j = 3 (4, the lower-left triangle) and
    // removes i + j >= 4 (6): volume 6/4 + 4/8 = 2, the triangle's area
    const Common P = pointParams(2);
    std::vector<MaterialPoint> pts;
    fillPolygon(pts, Vector2d::Zero(), 2, 2, Vector2d(1, 1), P, 1000.0, {{0, 0}, {2, 0}, {0, 2}});
    REQUIRE(pts.size() == 10);
    CHECK(near(totalVolume(pts), 2.0, 1e-12));
    int whole = 0, half = 0;
    for (const MaterialPoint& p : pts) {
      CAPTURE(p.mpC);
      CHECK((p.mpC(0) > 0 && p.mpC(1) > 0 && p.mpC.sum() < 2));  // inside the triangle
      CHECK(near(p.mpM, 1000.0 * p.vp0, 1e-12));
      if (near(p.vp0, 0.25, 1e-14)) ++whole;
      if (near(p.vp0, 0.125, 1e-14)) {
        ++half;  // centroid of the lower-left half of its square: corner + (1/6, 1/6)
        const Vector2d c0 = ((2.0 * p.mpC).array().floor() / 2.0).matrix();
        CHECK(near((p.mpC - c0 - Vector2d(1.0 / 6, 1.0 / 6)).norm(), 0, 1e-14));
        CHECK(int(std::lround(2 * c0.sum())) == 3);  // i + j = 3
        CHECK(near(p.lp0(0), 0.25 * std::sqrt(0.5), 1e-15));  // half lengths scaled by sqrt(1/2)
      }
    }
    CHECK(whole == 6);
    CHECK(half == 4);
  }

  TEST_CASE("fillPolygon: a square rotated by 30 degrees") {
    // side 2 about (2,2) on a 4 x 4 grid of unit cells, one point per cell: the four corner
    // cells lie wholly outside (removed); the other twelve are cut (truncated, none whole).
    // The inner cells [1,2]^2 (and by symmetry the other three) lose the triangle at their
    // outer corner, legs 1 - sqrt(3)/3 and sqrt(3) - 1: V = 2 - 2 sqrt(3)/3.
    const double c = std::sqrt(3.0) / 2, s = 0.5;  // cos 30, sin 30
    Polygon sq;
    for (Vector2d v : {Vector2d(1, -1), Vector2d(1, 1), Vector2d(-1, 1), Vector2d(-1, -1)})
      sq.push_back(Vector2d(2, 2) + Vector2d(c * v(0) - s * v(1), s * v(0) + c * v(1)));
    auto inside = [&](const Vector2d& p) {  // in the square's own axes
      const Vector2d q = p - Vector2d(2, 2);
      return std::abs(c * q(0) + s * q(1)) < 1 && std::abs(-s * q(0) + c * q(1)) < 1;
    };
    const Common P = pointParams(1);
    std::vector<MaterialPoint> pts;
    fillPolygon(pts, Vector2d::Zero(), 4, 4, Vector2d(1, 1), P, 1000.0, sq);
    CHECK(pts.size() == 12);  // 16 - 4 removed
    CHECK(near(totalVolume(pts), 4.0, 1e-12));
    int inner = 0;
    for (const MaterialPoint& p : pts) {
      CAPTURE(p.mpC);
      CHECK(inside(p.mpC));
      CHECK(p.vp0 < 1.0 - 1e-3);  // every point truncated
      if (p.mpC.minCoeff() > 1 && p.mpC.maxCoeff() < 3) {
        ++inner;
        CHECK(near(p.vp0, 2.0 - 2.0 * std::sqrt(3.0) / 3.0, 1e-14));
      }
    }
    CHECK(inner == 4);
    // finer, mp = 3: the same volume, every centroid inside
    std::vector<MaterialPoint> fine;
    fillPolygon(fine, Vector2d::Zero(), 4, 4, Vector2d(1, 1), pointParams(3), 1000.0, sq);
    CHECK(near(totalVolume(fine), 4.0, 1e-12));
    for (const MaterialPoint& p : fine) CHECK(inside(p.mpC));
  }
}

TEST_SUITE("addBoundary") {
  TEST_CASE("addBoundary: band width 1e-6 h and a type per segment and the solid polygon") {
    Analysis an;
    CHECK(!an.boundaries.has_value());  // none by default
    an.mesh = formCoord2D(10, 10, 0.1, 0.1);  // h = 10 mm
    Boundary& bottom = addBoundary(an, {{0, 0}, {0.1, 0}}, BoundaryType::Roller);
    CHECK(near(bottom.delta, 1e-8, 1e-20));
    addBoundary(an, {{0.1, 0}, {0.1, 0.1}}, BoundaryType::PrescribedNormal).du = {{-0.001, 0}};
    addBoundary(an, {{0.1, 0.1}, {0, 0.1}, {0, 0}}, {BoundaryType::Roller, BoundaryType::Fixed},
                1e-4);
    REQUIRE(boundariesOf(an).size() == 3);
    CHECK(boundariesOf(an)[1].du.size() == 1);
    CHECK(duAt(boundariesOf(an)[1], 1) == Vector2d(-0.001, 0));
    CHECK(boundariesOf(an)[2].segments() == 2);
    CHECK(boundariesOf(an)[2].type[1] == BoundaryType::Fixed);
    CHECK(near(boundariesOf(an)[2].delta, 1e-6, 1e-18));
    // the polygon round the solid: the joints once, the closing point not repeated
    const Polygon poly = solidPolygon(boundariesOf(an));
    REQUIRE(poly.size() == 4);
    CHECK(poly[0] == Vector2d(0, 0));
    CHECK(poly[1] == Vector2d(0.1, 0));
    CHECK(poly[2] == Vector2d(0.1, 0.1));
    CHECK(poly[3] == Vector2d(0, 0.1));
    CHECK_THROWS_AS(addBoundary(an, {{0, 0}}, BoundaryType::Fixed), InputError);
    const std::vector<BoundaryType> oneType = {BoundaryType::Fixed};  // two segments, one type
    CHECK_THROWS_AS(addBoundary(an, {{0, 0}, {1, 0}, {1, 1}}, oneType), InputError);
    CHECK_THROWS_AS(addBoundary(an, {{0, 0}, {0, 0}}, BoundaryType::Fixed), InputError);
  }

  TEST_CASE("addBoundary: the setups without implicit boundaries have none") {
    for (const char* name : {"compaction", "beam", "collapse", "shear", "stretch"}) {
      CAPTURE(name);
      const Setup* s = findSetup(name);
      REQUIRE(s != nullptr);
      CHECK(!s->setupGrid(s->params()).boundaries.has_value());
    }
  }
}
