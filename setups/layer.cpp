//--------------------------------------------------------------------------
// layer — elastic soil layer under its own weight: the mean-stress checkerboard of locking
//--------------------------------------------------------------------------
// A layer H = 10 m deep (rho = 2000 kg/m3, g = 10 m/s2, E = 100 MPa, nu = 0.49),
// half of it W = `width` H wide with a symmetry roller on x = 0 (u_x = 0), its base
// fixed (rough: u_x = u_y = 0 on y = 0), its far side x = W a roller (`sides=roller`)
// or free (`sides=free`, the grid then reaches `margin` cells past it). Square cells
// h = H / nels, mp x mp points per cell, small strain (SS), one load step.
// Reference: with rollers the layer is laterally confined (u_x = 0 everywhere, a 1-D
// column) and exact: sigma_yy = -rho g d, sigma_xx = sigma_zz = K0 sigma_yy with
// K0 = nu / (1 - nu), mean stress p = (sxx + syy + szz) / 3 = -rho g d (1 + 2 K0) / 3
// (d = H - Y the depth; nu -> 0.5: the hydrostatic -rho g d). A 1-D column has no
// locking mode: the points' p is constant in each cell (a staircase about the line).
// With a free side the layer spreads over its rough base; the isochoric part of that
// flow locks (nu -> 0.5) and the points' p oscillates from row to row within a cell
// (the checkerboard), largest near the free side and the base corner. Far from the
// free side (x < W - 4 H) the state is the confined one, the reference there.
// results: checker_rms, checker_max = the spread of the points' p about the mean of
// their cell (RMS and largest over all points) / (rho g H): the oscillation alone,
// 0 for any field constant in a cell (the 1-D staircase, a cell-averaged pressure);
// dev_rms, dev_max = p - p_ref over the points where the reference holds (all with
// rollers; x < W - 4 H with a free side) / (rho g H), which holds the staircase of the
// cells (+-rho g h / 4 at 2 x 2 points); dev_cell_rms, dev_cell_max = the mean of p over
// each cell's points against the reference's mean there (the staircase removed: round-off
// with rollers); dev_all_rms = p - p_ref over every point, the free side's included (where
// p_ref is not the answer: the free side's real departure from the confined state counts
// there, as the checkerboard does); points_ref = the points counted.
//   ample layer sides=free nels=8
// Outputs: Analysis · results
// Tests:   tests/test_benchmarks.cpp, CTest setup.layer
//--------------------------------------------------------------------------
#include "ample/errors.h"
#include "formCoord2D.h"
#include "setupHelpers.h"
#include <cmath>
#include <map>

namespace ample::layer {

static const double H = 10.0;             // layer depth (m)

// the parameters and their defaults (their ranges and help: params)
struct Layer : Common {
  int nels = 4, width = 6;
  int sides = 1;                          // 0 roller, 1 free
  int margin = 1;
  double rho = 2000, g = 10;
  Layer() {
    formulation = Formulation::SS;        // one step of the linear problem
    E = 100e6;
    nu = 0.49;
  }
};

Params params(Layer& p) {
  Params P = commonParams(p);
  param(P, "nels", p.nels).integer(1, 256).help("cells over the depth: h = H / nels, H = 10 m");
  param(P, "width", p.width).integer(1, 20).help("half width W / H");
  param(P, "sides", p.sides).choice(0, {"roller", "free"})
      .help("far side x = W: roller (laterally confined, exact 1-D state) or free");
  param(P, "margin", p.margin).integer(1, 16).help("grid cells past a free side");
  param(P, "rho", p.rho).above(0).help("density (kg/m3)");
  param(P, "g", p.g).above(0).help("gravitational acceleration (m/s2)");
  return P;
}

Analysis setupGrid(const Layer& p) {
  const int nels = p.nels, nx = nels * p.width;
  const bool free = p.sides == 1;
  const int extra = free ? p.margin : 0;
  const double h = H / nels, W = nx * h, eps = 1e-9 * h;
  Analysis an = baseAnalysis(p);
  an.g = p.g;
  an.mesh = formCoord2D(nx + extra, nels + 1, (nx + extra) * h, H + h);  // a row above the top
  fixDofs(an.mesh, 0, [&](double X, double Y) { return X < eps || Y < eps || (!free && X > W - eps); });
  fixDofs(an.mesh, 1, [&](double, double Y) { return Y < eps; });
  fillBlock(an.mpData, Vector2d::Zero(), nx, nels, an.mesh.h, p, p.rho);
  return an;
}

Results results(const Analysis& an, const Layer& l) {
  const double rho = l.rho, g = l.g, nu = l.nu, K0 = nu / (1 - nu);
  const double scale = rho * g * H, h = H / l.nels, W = h * l.nels * l.width;
  const bool free = l.sides == 1;
  auto p = [](const MaterialPoint& mp) { return (mp.sig(0) + mp.sig(1) + mp.sig(2)) / 3; };
  auto cell = [&](const MaterialPoint& mp) {                        // the cell of its start
    return int(std::floor(mp.X0(1) / h)) * 100000 + int(std::floor(mp.X0(0) / h));
  };
  std::map<int, std::pair<double, int>> sum;                       // cell -> sum of p, count
  std::map<int, std::pair<double, double>> ref;                    // cell -> sums of p, p_ref
  for (const MaterialPoint& mp : an.mpData) {
    auto& s = sum[cell(mp)];
    s.first += p(mp);
    ++s.second;
  }
  double c2 = 0, cMax = 0, d2 = 0, dMax = 0, a2 = 0;
  int nRef = 0;
  for (const MaterialPoint& mp : an.mpData) {
    const auto& s = sum[cell(mp)];
    const double c = (p(mp) - s.first / s.second) / scale;
    c2 += c * c;
    cMax = std::max(cMax, std::abs(c));
    const double pRef = -rho * g * (H - mp.X0(1)) * (1 + 2 * K0) / 3;
    a2 += std::pow((p(mp) - pRef) / scale, 2);                       // every point, the free side's too
    if (free && mp.X0(0) > W - 4 * H) continue;
    const double d = (p(mp) - pRef) / scale;
    d2 += d * d;
    dMax = std::max(dMax, std::abs(d));
    ++nRef;
    ref[cell(mp)].first += p(mp) / s.second;
    ref[cell(mp)].second += pRef / s.second;
  }
  double e2 = 0, eMax = 0;                                         // cell means against the reference's
  for (const auto& c : ref) {
    const double e = (c.second.first - c.second.second) / scale;
    e2 += e * e;
    eMax = std::max(eMax, std::abs(e));
  }
  Results r{{"checker_rms", std::sqrt(c2 / an.mpData.size())}, {"checker_max", cMax},
            {"dev_rms", nRef ? std::sqrt(d2 / nRef) : NAN}, {"dev_max", nRef ? dMax : NAN},
            {"dev_cell_rms", nRef ? std::sqrt(e2 / ref.size()) : NAN}, {"dev_cell_max", nRef ? eMax : NAN},
            {"dev_all_rms", std::sqrt(a2 / an.mpData.size())},
            {"points_ref", double(nRef)}};
  if (!nRef) {
    r.undefined("dev_rms", "no point lies more than 4 H from the free side (width <= 4)");
    for (const char* name : {"dev_max", "dev_cell_rms", "dev_cell_max"})
      r.undefined(name, "no point lies more than 4 H from the free side (width <= 4)");
  }
  return r;
}

// this setup's line in the table of setups/setups.cpp
SetupCalls calls() { return {params, setupGrid, results}; }

}  // namespace ample::layer
