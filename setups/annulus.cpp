//--------------------------------------------------------------------------
// annulus — elastic annulus twisted by a manufactured body force ([Lagrangian] sec 7.4)
//--------------------------------------------------------------------------
// Ri = 0.75 m, Ro = 1.25 m, E = 1 Pa, nu = 0, alpha = 0.1 rad (eq 44) over 10
// load steps; the nodes on both circles fixed. Background mesh: linear
// triangles, ns = round(2 pi Ro / h) sectors (h = the chord length on the
// outer circle, 0.4363 m = 18 sectors; the paper's five meshes are 18, 36,
// 72, 144, 288) by nr = max(1, round(2 ns / 18)) rings (2 rings for 18
// sectors, so the five meshes are nested halvings), each quad cut in two
// along alternating diagonals. Points: mpTri per triangle, n = k^2: the
// triangle cut into k^2 similar ones (k per edge), one point at each centroid;
// n = 2 k^2: each of those cut again in two from the midpoint of its longest
// edge. Volume = area / n. MPM (the paper's), or CPDI1/CPDI2 with a square
// domain of that area about each point (the corners of the points next to the
// circles lie outside the mesh: cornerCell continues the edge cell's basis;
// GIMP: InputError). Body force: the exact one
// of the motion with alpha lf at load factor lf (bfLinear=1: lf times the
// full one). Error (our reading of the paper's "absolute displacement error",
// after eq 42): sum_p |u_p - u_a(X_p)| V0_p / V0 (m).
// Outputs: results: error, max point error, points, nodes
// Tests:   tests/test_annulus.cpp; CTest setup.annulus
//--------------------------------------------------------------------------
#include "annulus.h"
#include "ample/errors.h"
#include "ample/meshes/generalMesh.h"
#include "setupHelpers.h"
#include <cmath>

namespace ample::annulus {

double theta(double R, double alpha) {
  return alpha * 16 * std::pow(R - Ri, 2) * std::pow(R - Ro, 2) / std::pow(Ri - Ro, 4);
}

Vector2d displacement(const Vector2d& X, double alpha) {
  const double t = theta(X.norm(), alpha);
  return Vector2d(std::cos(t) * X(0) - std::sin(t) * X(1) - X(0),
                  std::sin(t) * X(0) + std::cos(t) * X(1) - X(1));
}

Vector2d bodyForce(const Vector2d& X, double alpha, double G) {
  const double R = X.norm(), c = 16 * alpha / std::pow(Ri - Ro, 4);
  const double p = (R - Ri) * (R - Ro), dp = 2 * R - Ri - Ro;   // theta = c p^2
  const double dth = 2 * c * p * dp, ddth = 2 * c * (dp * dp + 2 * p);
  const double gam = R * dth, dgam = dth + R * ddth;              // gamma, gamma'
  const double s = std::sqrt(1 + gam * gam / 4), k = std::asinh(gam / 2);
  const double f = k / s, df = (0.5 - k * gam / (4 * s)) / (s * s);
  const double br = G * (f + gam * df) * dgam + 2 * G * gam * f / R;
  const double bp = -2 * G * (df * dgam + 2 * f / R);
  const double phi = std::atan2(X(1), X(0)) + theta(R, alpha);   // current angle
  return Vector2d(br * std::cos(phi) - bp * std::sin(phi), br * std::sin(phi) + bp * std::cos(phi));
}

// the parameters and their defaults (their ranges and help: params)
struct Annulus : Common {
  double h = 0.4363;
  int mpTri = 4;
  double alpha = 0.1;
  int bfLinear = 0;
  Annulus() {
    lstps = 10;
    mpType = MpType::MPM;
    E = 1.0;
    nu = 0.0;
  }
};

Params params(Annulus& p) {
  Params P = commonParams(p);
  param(P, "h", p.h).range(0.005, 1).help("mesh size: chord on the outer circle (m)");
  param(P, "mpTri", p.mpTri).integer(1, 200).help("points per triangle: k^2 or 2 k^2");
  param(P, "alpha", p.alpha).range(-1, 1).help("rotation alpha of eq 44 (rad)");
  param(P, "bfLinear", p.bfLinear).integer(0, 1)
      .help("0: body force of the motion at alpha lf; 1: lf times the full one");
  return P;
}

// the points of triangle (a, b, c) by the rule above
static void triPoints(const Vector2d& a, const Vector2d& b, const Vector2d& c, int k, bool halve,
                      std::vector<std::array<Vector2d, 3>>& out) {
  auto P = [&](int i, int j) { return a + (b - a) * double(i) / k + (c - a) * double(j) / k; };
  std::vector<std::array<Vector2d, 3>> sub;
  for (int j = 0; j < k; ++j)
    for (int i = 0; i + j < k; ++i) {
      sub.push_back({P(i, j), P(i + 1, j), P(i, j + 1)});
      if (i + j + 1 < k) sub.push_back({P(i + 1, j), P(i + 1, j + 1), P(i, j + 1)});
    }
  for (const auto& t : sub) {
    if (!halve) { out.push_back(t); continue; }
    int e = 0;  // longest edge t[e] -> t[e+1]
    for (int q = 1; q < 3; ++q)
      if ((t[(q + 1) % 3] - t[q]).norm() > (t[(e + 1) % 3] - t[e]).norm()) e = q;
    const Vector2d m = 0.5 * (t[e] + t[(e + 1) % 3]), o = t[(e + 2) % 3];
    out.push_back({t[e], m, o});
    out.push_back({m, t[(e + 1) % 3], o});
  }
}

// ns sectors by nr rings between Ri and Ro, each quad cut in two along alternating
// diagonals, anticlockwise: node j ns + i at radius Ri + (Ro - Ri) j / nr, angle 2 pi i / ns
static void ringMesh(int ns, int nr, Eigen::MatrixX2d& coord, Eigen::MatrixXi& etpl) {
  coord.resize((nr + 1) * ns, 2);
  for (int j = 0; j <= nr; ++j)
    for (int i = 0; i < ns; ++i) {
      const double r = Ri + (Ro - Ri) * j / nr, a = 2 * M_PI * i / ns;
      coord.row(j * ns + i) << r * std::cos(a), r * std::sin(a);
    }
  etpl.resize(2 * nr * ns, 3);
  int e = 0;
  for (int j = 0; j < nr; ++j)
    for (int i = 0; i < ns; ++i) {
      const int n0 = j * ns + i, n1 = j * ns + (i + 1) % ns, n2 = n1 + ns, n3 = n0 + ns;
      if ((i + j) % 2) { etpl.row(e++) << n0, n3, n2; etpl.row(e++) << n0, n2, n1; }
      else { etpl.row(e++) << n0, n3, n1; etpl.row(e++) << n3, n2, n1; }
    }
}

Analysis setupGrid(const Annulus& p) {
  Analysis an = baseAnalysis(p);
  const int ns = int(std::lround(2 * M_PI * Ro / p.h));
  const int nr = std::max(1, int(std::lround(2.0 * ns / 18)));
  const int n = p.mpTri;
  int k = int(std::lround(std::sqrt(double(n)))), kh = int(std::lround(std::sqrt(n / 2.0)));
  const bool halve = k * k != n;
  if (halve) k = kh;
  if (k * k * (halve ? 2 : 1) != n) throw InputError("mpTri=" + std::to_string(n) + ": must be k^2 or 2 k^2");
  Eigen::MatrixX2d coord;
  Eigen::MatrixXi etpl;
  ringMesh(ns, nr, coord, etpl);
  an.mesh = generalMesh(coord, etpl);
  for (int i = 0; i < 2; ++i)
    fixDofs(an.mesh, i, [](double X, double Y) {
      const double R = std::hypot(X, Y);
      return std::abs(R - Ri) < 1e-9 || std::abs(R - Ro) < 1e-9;
    });
  if (p.mpType == MpType::GIMP)  // GIMP needs the regular grid
    throw InputError("mpType=2 (GIMP) needs the regular grid; the annulus is a triangle mesh "
                     "(use mpType=1 MPM, 3 CPDI1 or 4 CPDI2)");
  for (int c = 0; c < an.mesh.nels(); ++c) {
    std::vector<std::array<Vector2d, 3>> tris;
    const Vector2d a = coord.row(etpl(c, 0)), b = coord.row(etpl(c, 1)), d = coord.row(etpl(c, 2));
    triPoints(a, b, d, k, halve, tris);
    for (const auto& t : tris) {
      const double A = 0.5 * std::abs((t[1] - t[0]).x() * (t[2] - t[0]).y() - (t[1] - t[0]).y() * (t[2] - t[0]).x());
      MaterialPoint mp = cellPoint((t[0] + t[1] + t[2]) / 3, A, p, 0.0);  // CPDI: a square of area A
      mp.cmType = CmType::Elastic;
      an.mpData.push_back(mp);
    }
  }
  const double alpha = p.alpha, G = p.E / (2 * (1 + p.nu));
  const bool linear = p.bfLinear == 1;
  an.bodyForce = [=](const Vector2d& X, double lf) {
    return linear ? Vector2d(lf * bodyForce(X, alpha, G)) : bodyForce(X, lf * alpha, G);
  };
  return an;
}

Results results(const Analysis& an, const Annulus& p) {
  const double alpha = p.alpha;
  double err = 0, V = 0, emax = 0;
  for (const MaterialPoint& mp : an.mpData) {
    const double e = (mp.u - displacement(mp.X0, alpha)).norm();
    err += e * mp.vp0;
    V += mp.vp0;
    emax = std::max(emax, e);
  }
  return {{"error", err / V}, {"max_point_error", emax}, {"points", double(an.mpData.size())},
          {"nodes", double(an.mesh.nodes())}};
}

// this setup's line in the table of setups/setups.cpp
SetupCalls calls() { return {params, setupGrid, results}; }

}  // namespace ample::annulus
