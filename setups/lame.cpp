//--------------------------------------------------------------------------
// lame — thick-walled cylinder under internal pressure (Lame), plane strain, elastic
//--------------------------------------------------------------------------
// A quarter of the ring a <= r <= b (a = 1 m, b = 2 m), E = 10 MPa, `nu` (0.3; up
// to 0.4999, where bilinear MPM locks), rollers on the x and y axes: the grid's
// origin is the cylinder's centre, so both axes are grid lines (u_y = 0 on y = 0,
// u_x = 0 on x = 0). Square cells h = (b - a) / nels over [0, b + h]^2.
// Points in polar rings: mp x nels rings across the wall (dr = (b - a) / (mp nels))
// and nt = round((pi/2) r_mid / dr) sectors (dtheta = (pi/2) / nt), one point at the
// centre (r_c, theta_c) of each ring sector with its exact area r_c dr dtheta as volume
// (unit thickness). mpType=MPM, or CPDI2 with the sector's four corners as its domain
// (volume: that quadrilateral's area); GIMP and CPDI1 are refused (their rectangles
// and parallelograms cannot follow the rings).
// The pressure p acts as point forces (mp.fp, [AMPLE] eq 28) on the innermost ring:
// p a dtheta radially outward (the total at load factor 1; the main loop scales fext
// by the load factor, detExtForce), so the inner surface is loaded at r = a + dr/2.
// Exact (plane strain): u_r = A r + C / r; eps_rr = A - C / r^2, eps_tt = A + C / r^2,
// sigma_rr = 2 (lambda + mu) A - 2 mu C / r^2 with sigma_rr(a) = -p, sigma_rr(b) = 0:
//   2 mu C = p a^2 b^2 / (b^2 - a^2),  2 (lambda + mu) A = p a^2 / (b^2 - a^2),
//   u_r(r) = (1 + nu) p a^2 / (E (b^2 - a^2)) [ (1 - 2 nu) r + b^2 / r ],
//   sigma_rr, sigma_tt = p a^2 / (b^2 - a^2) (1 -+ b^2 / r^2), sigma_zz = nu (sigma_rr + sigma_tt).
// results: error_inner = the mean over the inner ring of (u_r - u_r,a(r)) / u_r,a(r);
// error_max = max over the points of |u - u_a(X)| / max u_r,a; stress_rms = RMS over the
// points of |sigma - sigma_a| (rr, tt, zz, rt) / p; ur_inner and ur_inner_a (means, m).
// Small strain (SS, one load step) by default; UL with a small p (the default 10 kPa
// gives u_r(a) / a = 1.7e-3 at nu = 0.3).
//   ample lame nels=8 nu=0.4999
// Outputs: Analysis · results
// Tests:   tests/test_benchmarks.cpp, CTest setup.lame
//--------------------------------------------------------------------------
#include "ample/errors.h"
#include "formCoord2D.h"
#include "setupHelpers.h"
#include <cmath>

namespace ample::lame {

static const double a = 1.0, b = 2.0;     // inner and outer radii (m)

// the parameters and their defaults (their ranges and help: params)
struct Lame : Common {
  int nels = 4;
  double p = 10e3;
  Lame() {
    formulation = Formulation::SS;                 // one step of the linear problem
    mpType = MpType::MPM;
    E = 10e6;
    nu = 0.3;
  }
};

Params params(Lame& l) {
  Params P = commonParams(l);
  param(P, "nels", l.nels).integer(1, 256).help("cells across the wall: h = (b - a) / nels, a = 1 m, b = 2 m");
  param(P, "p", l.p).above(0).atMost(1e6).help("internal pressure (Pa)");
  return P;
}

// the exact radial displacement at r
static double urExact(double r, const Lame& l) {
  const double E = l.E, nu = l.nu, p = l.p;
  return (1 + nu) * p * a * a / (E * (b * b - a * a)) * ((1 - 2 * nu) * r + b * b / r);
}

Analysis setupGrid(const Lame& l) {
  const MpType type = l.mpType;
  if (type != MpType::MPM && type != MpType::CPDI2)
    throw InputError("lame: mpType=" + number(int(l.mpType)) +
                     " is not allowed: the points lie in polar rings; use mpType=MPM or CPDI2");
  const int nels = l.nels, mp = l.mp, nr = mp * nels;
  const double h = (b - a) / nels, dr = (b - a) / nr, p = l.p;
  const int nt = std::max(1, int(std::lround(0.5 * M_PI * 0.5 * (a + b) / dr)));
  const double dt = 0.5 * M_PI / nt;
  checkPointMemory(size_t(nr) * nt);
  Analysis an = baseAnalysis(l);
  const int n = 2 * nels + 1;                       // b / h cells and one past the ring
  an.mesh = formCoord2D(n, n, n * h, n * h);
  const double eps = 1e-9 * h;
  fixDofs(an.mesh, 0, [&](double X, double) { return X < eps; });   // x = 0: u_x = 0
  fixDofs(an.mesh, 1, [&](double, double Y) { return Y < eps; });   // y = 0: u_y = 0
  for (int i = 0; i < nr; ++i)
    for (int j = 0; j < nt; ++j) {
      const double r0 = a + i * dr, rc = r0 + dr / 2, t0 = j * dt, tc = t0 + dt / 2;
      const Vector2d er(std::cos(tc), std::sin(tc));
      MaterialPoint pt = cellPoint(rc * er, rc * dr * dt, l, 1.0);
      if (type == MpType::CPDI2) {                                  // the sector's corners
        const double rr[4] = {r0, r0 + dr, r0 + dr, r0}, tt[4] = {t0, t0, t0 + dt, t0 + dt};
        for (int c = 0; c < 4; ++c) pt.cpdi->xc.col(c) = rr[c] * Vector2d(std::cos(tt[c]), std::sin(tt[c]));
        const Eigen::Matrix<double, 2, 4>& x = pt.cpdi->xc;
        const Vector2d d1 = x.col(2) - x.col(0), d2 = x.col(3) - x.col(1);
        pt.vp = pt.vp0 = 0.5 * std::abs(d1(0) * d2(1) - d1(1) * d2(0));
        pt.mpM = pt.vp0;
      }
      if (i == 0) pt.fp = p * a * dt * er;                          // the pressure on the inner ring
      an.mpData.push_back(pt);
    }
  return an;
}

Results results(const Analysis& an, const Lame& l) {
  const double nu = l.nu, p = l.p, k = p * a * a / (b * b - a * a);
  const double uMax = urExact(a, l);                                // u_r,a is largest at r = a
  double inner = 0, ur = 0, urA = 0, errMax = 0, s2 = 0;
  int nIn = 0;
  const double rIn = an.mpData.empty() ? 0 : an.mpData.front().X0.norm();
  for (const MaterialPoint& mp : an.mpData) {
    const double r = mp.X0.norm(), c = mp.X0(0) / r, s = mp.X0(1) / r;
    const double uA = urExact(r, l);
    errMax = std::max(errMax, (mp.u - uA * mp.X0 / r).norm() / uMax);
    if (std::abs(r - rIn) < 1e-9) {
      const double uR = mp.u(0) * c + mp.u(1) * s;
      inner += (uR - uA) / uA;
      ur += uR;
      urA += uA;
      ++nIn;
    }
    const double sRR = k * (1 - b * b / (r * r)), sTT = k * (1 + b * b / (r * r));
    const double rr = mp.sig(0) * c * c + mp.sig(1) * s * s + 2 * mp.sig(3) * c * s;
    const double tt = mp.sig(0) * s * s + mp.sig(1) * c * c - 2 * mp.sig(3) * c * s;
    const double rt = (mp.sig(1) - mp.sig(0)) * c * s + mp.sig(3) * (c * c - s * s);
    const double zz = mp.sig(2) - nu * (sRR + sTT);
    s2 += (rr - sRR) * (rr - sRR) + (tt - sTT) * (tt - sTT) + zz * zz + 2 * rt * rt;
  }
  return {{"error_inner", inner / nIn}, {"error_max", errMax},
          {"stress_rms", std::sqrt(s2 / an.mpData.size()) / p},
          {"ur_inner", ur / nIn}, {"ur_inner_a", urA / nIn}, {"points", double(an.mpData.size())}};
}

// this setup's line in the table of setups/setups.cpp
SetupCalls calls() { return {params, setupGrid, results}; }

}  // namespace ample::lame
