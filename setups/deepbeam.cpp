//--------------------------------------------------------------------------
// deepbeam — a deep cantilever under its own weight, fixed by an implicit boundary
//             ([Boundaries] sec 5.2, tables II and III)
//--------------------------------------------------------------------------
// A 100 x 100 mm body (L = 0.1 m), its left side fully fixed (u = 0) by an
// implicit boundary (BoundaryType::Fixed), loaded by the body force
// 1 N/mm2 of the paper (plane strain, unit thickness: 1 N/mm3 = 1e9 N/m3,
// here rho g with g = 10 m/s2) in -y in one load step. Standard MPM points
// (mpType 1), mp x mp per cell, small strain (formulation SS), E = 1000 MPa,
// nu = 0.3, delta = 1e-6 h. The paper does not say where the body sits in the
// grid: here its left side lies on the grid line x = 0 (the implicit boundary
// on a grid line belongs to the cell on the solid side, cutCells), its sides
// on grid lines (L / h whole), and the grid leaves room for the body to sag:
// 60 mm below it, 30 mm to its right and one cell above (empty cells change
// nothing: their nodes are not free dofs). The dofs of the body's cells,
// 2 (L/h + 1)^2, are the paper's table III counts (242 at h = 10 mm).
// Point A (fig 14, not in the text): the free end's bottom corner (L, 0) or
// its mid-height (L, L/2) (parameter A). v(A) is the nodal y-displacement of
// the grid at A (a node at both for the h of the tables; linear along the
// edge x = L otherwise), the same in both solutions.
// The reference (the paper's "FE solution using the same mesh"): the same
// program with one point at each 2 x 2 Gauss position of every cell of the body
// (weight = volume h^2 / 4) and the left side fixed on the grid nodes of x = 0
// (fixDofs): with small strain and standard MPM points, the sum over points of
// B^T D B V_p and N rho g V_p is then exactly bilinear FE with 2 x 2 Gauss
// quadrature. `reference=1` runs that model; results() solves it once more
// (one linear solve: SS is linear) beside every run to compare (also when the
// run itself takes formulation UL or PC: the reference stays small strain).
// Outputs: results: rA = |v(A) - v_FE(A)| / |v_FE(A)| (tables II, III), both
//          corners' errors, v(A) and v_FE(A) (mm), dofs (2 x linked nodes), points
// Tests:   tests/test_ibSetups.cpp
//--------------------------------------------------------------------------
#include "ample/detExtForce.h"
#include "ample/detFDoFs.h"
#include "ample/remedies/loneNodes.h"
#include "ample/formulations/detMPsForm.h"
#include "ample/cpdi/elemMPinfoCPDI.h"
#include "ample/errors.h"
#include "formCoord2D.h"
#include "ample/linSolve.h"
#include "setupHelpers.h"
#include <cmath>
#include <set>

namespace ample::deepbeam {

static const double L = 0.1;                           // side of the body (m)
static const double g = 10.0;                          // body force = rho g (m/s2)
static const double roomBelow = 0.06, roomRight = 0.03;  // grid room for the sag (m)

// the parameters and their defaults (their ranges and help: params)
struct Deepbeam : IbCommon {
  double h = 0.01, b = 1e9;
  int A = 0;                                         // 0 bottom, 1 mid
  int reference = 0;                                 // 0 IB, 1 FE
  Deepbeam() {
    lstps = 1;
    mp = 4;
  }
};

Params params(Deepbeam& p) {
  Params P = ibCommonParams(p);
  P.named("lstps").integer(1, 1).help("load steps: one (the paper's; v(A) is its nodal solution)");
  P.named("mp").integer(1, 40);                      // table II goes to 40 x 40
  param(P, "h", p.h).range(2e-4, 0.05).help("grid spacing (m); L / h a whole number (L = 0.1 m)");
  param(P, "b", p.b).atLeast(0).help("body force in -y (N/m3; the paper's 1 N/mm2 = 1e9)");
  param(P, "A", p.A).choice(0, {"bottom", "mid"})
      .help("point A of fig 14 (not in the text): the free end's bottom corner (L, 0) "
            "or its mid-height (L, L/2)");
  param(P, "reference", p.reference).choice(0, {"IB", "FE"})
      .help("IB: mp x mp points, the implicit fixed side (the paper's MPM); FE: points at "
            "the 2 x 2 Gauss positions and nodal fixity on x = 0 (bilinear FE); rA always "
            "compares with this model in small strain (SS), whatever the formulation");
  return P;
}

static int cells(double length, double h) { return int(std::ceil(length / h - 1e-9)); }

Analysis setupGrid(const Deepbeam& p) {
  const double h = p.h, rho = p.b / g;
  const int nL = int(std::lround(L / h));
  if (std::abs(nL * h - L) > 1e-9 * L)
    throw InputError("h: L / h must be a whole number (L = 0.1 m), got h = " + std::to_string(h));
  const int nx = nL + cells(roomRight, h), nBelow = cells(roomBelow, h), ny = nBelow + nL + 1;
  Analysis an = baseAnalysis(p);
  an.g = g;
  an.mesh = formCoord2D(nx, ny, nx * h, ny * h);
  const Vector2d corner(0.0, nBelow * h);              // lower-left corner of the body
  if (p.reference == 0) {
    addBoundary(an, {corner + Vector2d(0, L), corner}, BoundaryType::Fixed, p.delta);
    ibSettings(an, p);
    fillBlock(an.mpData, corner, nL, nL, an.mesh.h, p, rho);
    return an;
  }
  for (int i = 0; i < 2; ++i)                           // the support on the nodes of x = 0
    fixDofs(an.mesh, i, [&](double X, double) { return X < 1e-9 * h; });
  Deepbeam one = p;                                     // one point in each quarter "cell" of
  one.mp = 1;                                           // side h/2 about a Gauss position
  const double a = 0.5 / std::sqrt(3.0);                // Gauss position: centre +- h/(2 sqrt 3)
  const Vector2d q = an.mesh.h / 2;
  an.mpData.reserve(4 * size_t(nL) * nL);              // fillBlock below adds one at a time
  for (int ey = 0; ey < nL; ++ey)
    for (int ex = 0; ex < nL; ++ex)
      for (int k = 0; k < 4; ++k) {
        const Vector2d c = corner + Vector2d((ex + 0.5) * h, (ey + 0.5) * h);
        const Vector2d gp = c + h * Vector2d(k % 2 ? a : -a, k / 2 ? a : -a);
        fillBlock(an.mpData, gp - q / 2, 1, 1, q, one, rho);  // at gp, volume h^2 / 4
      }
  return an;
}

// the nodal solution of a small-strain model in one linear solve (SS: Kt does not
// depend on u, so solve()'s first Newton pass is this and the second corrects round-off)
static Eigen::VectorXd linearSolution(Analysis& an) {
  const int nDoF = an.mesh.nDoF();
  elemMPinfoCPDI(an.mesh, an.mpData);
  const Eigen::VectorXd fext = detExtForce(nDoF, an.g, an.mpData);
  const std::vector<int> fd = detFDoFsLone(an.mesh, an.mpData);
  const DetMPsOut mps = detMPsOf(Eigen::VectorXd::Zero(nDoF), an.mpData, Formulation::SS);
  return linSolve(an.mesh.bc, mps.Kt, fext, 1, fd).duvw;
}

// v at (L, y) on the right side of the body: nodal, linear between the nodes of x = L
static double vAt(const Mesh& mesh, const Eigen::VectorXd& uvw, double y) {
  const double h = mesh.h(1), s = y / h;
  const int ix = int(std::lround(L / mesh.h(0))), iy = std::min(int(std::floor(s + 1e-9)), mesh.nelsy - 1);
  const double w = std::max(0.0, s - iy);
  auto v = [&](int j) { return uvw(dof(j * (mesh.nelsx + 1) + ix, 1)); };
  return w < 1e-9 ? v(iy) : (1 - w) * v(iy) + w * v(iy + 1);
}

Results results(const Analysis& an, const Deepbeam& p) {
  Deepbeam q = p;
  q.reference = 1;
  Analysis fe = setupGrid(q);
  const Eigen::VectorXd uFE = linearSolution(fe);
  const double y0 = cells(roomBelow, p.h) * p.h;
  const Eigen::VectorXd u = an.uvw.size() == an.mesh.nDoF() ? an.uvw   // none: no step converged
                                                             : Eigen::VectorXd::Zero(an.mesh.nDoF());
  auto err = [&](double y, double& v, double& vFE) {
    v = vAt(an.mesh, u, y);
    vFE = vAt(fe.mesh, uFE, y);
    return vFE != 0 ? std::abs(v - vFE) / std::abs(vFE) : NAN;
  };
  double vb, vbFE, vm, vmFE;
  const double rb = err(y0, vb, vbFE), rm = err(y0 + L / 2, vm, vmFE);
  const bool mid = p.A == 1;
  std::set<int> linked;                                 // nodes of the points (this step)
  for (const MaterialPoint& mp : an.mpData) linked.insert(mp.nIN.begin(), mp.nIN.begin() + mp.nn);
  Results r{{"rA", mid ? rm : rb}, {"vA_mm", 1e3 * (mid ? vm : vb)}, {"vA_FE_mm", 1e3 * (mid ? vmFE : vbFE)},
            {"rA_bottom", rb}, {"rA_mid", rm}, {"dofs", 2.0 * linked.size()},
            {"points", double(an.mpData.size())}};
  for (const char* k : {"rA", "rA_bottom", "rA_mid"})
    if (p.b == 0) r.undefined(k, "no load (b = 0): the error is relative to v_FE(A) = 0");
  return r;
}

// this setup's line in the table of setups/setups.cpp
SetupCalls calls() { return {params, setupGrid, results}; }

}  // namespace ample::deepbeam
