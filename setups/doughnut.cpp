//--------------------------------------------------------------------------
// doughnut — twist of a confined annulus, MPM / CPDI1 / CPDI2 / FE ([CPDI] sec 3.2)
//--------------------------------------------------------------------------
// Fig 5: outer circle R = 10 fixed; hole a circle A = B = 5 or an ellipse
// A = 6, B = 4 (hole=1); E = 1e6, nu = 0, von Mises rho_y = 1e6 (rhoY); the
// inner boundary rotated dalpha = 5 degrees clockwise per load step, as
// prescribed nodal displacement increments du = (R(-dalpha) - I) x of the
// inner nodes at their current x. Mesh: structured annulus of nr x nc
// quadrilaterals (10 x 72; fig 8: 5 x 18), node (i, j) at
//   x = (1 - i/nr) (A cos t, B sin t) + (i/nr) R (cos t, sin t), t = 2 pi j / nc
// with t graded by refine = k: t = tau - (1 - i/nr) k sin(2 tau)/2, tau =
// 2 pi j / nc (k > 0: smaller cells at the ends of the ellipse's long axis,
// as the paper refines there by an amount it does not give, fading to uniform
// at the outer circle, whose chords stay short; k = 0 uniform). Four points
// per cell (fillCells: 2 x 2 Gauss positions for MPM and FE, sub-cell domains
// for CPDI). "Moving mesh" (sec 3.2): for MPM and CPDI the mesh is rebuilt
// at the start of each step rigidly rotated with the inner boundary,
// R(-(lstp - 1) dalpha) X (beforeStep); the FE mode (fem=1) moves it with
// the nodes instead. Sampling points along theta = 0 (the nodes i = 0..nr of
// j = 0): FE: the nodes' displacements; MPM, CPDI1: extra points at those
// interior nodes with a square domain of edge 0.001 (V = 1e-6; the end nodes
// give their prescribed displacements: a tiny domain there would stick out of
// the mesh); CPDI2: the corner of a domain that starts on the node. With
// nc = 18 (fig 8) a 5 degree turn is not a multiple of the cell angle 20
// degrees: the rotated outer chords cut off the fixed material's CPDI corners
// on the outer circle (they take the continued basis of the edge cell,
// cornerCell); a point itself outside a chord stops the run.
// Outputs: history.csv per step: lstp, alpha (deg), f = sum of the reaction
//          magnitudes on the inner nodes (reactionOver), f / (C E), C = 2 pi A
//          (the inner circumference; for the ellipse still 2 pi A, stated);
//          torque = the clockwise moment of those reactions about the centre at
//          the nodes' end-of-step positions, torque / (C_h E), C_h = the hole's
//          perimeter (fig 11: the ellipse's, Ramanujan's formula);
//          results: fNorm at the last step, ux_i, uy_i of the sampling points
// Tests:   tests/test_femode.cpp; CTest setup.doughnut
//--------------------------------------------------------------------------
#include "ample/errors.h"
#include "ample/meshes/generalMesh.h"
#include "setupHelpers.h"
#include <cmath>
#include <memory>

namespace ample::doughnut {

// the parameters and their defaults (their ranges and help: params)
struct Doughnut : Common {
  int nr = 10, nc = 72;
  int hole = 0;                                     // 0 circle, 1 ellipse
  double refine = 0, dalpha = 5;
  int fem = 0;
  Doughnut() {
    lstps = 2;
    mpType = MpType::MPM;
    cmType = CmType::VonMises;
    E = 1e6;
    nu = 0.0;
    rhoY = 1e6;
  }
};

Params params(Doughnut& p) {
  Params P = commonParams(p);
  param(P, "nr", p.nr).integer(1, 400).help("cells along the radius (paper 10; fig 8: 5)");
  param(P, "nc", p.nc).integer(4, 4000).help("cells round the annulus (paper 72; fig 8: 18)");
  param(P, "hole", p.hole).choice(0, {"circle", "ellipse"})
      .help("inner boundary: circle A = B = 5 or ellipse A = 6, B = 4 (fig 5)");
  param(P, "refine", p.refine).range(0, 0.9)
      .help("circumferential grading k at the hole: theta = tau - (1 - i/nr) k sin(2 tau)/2, cells "
            "(1 + k)/(1 - k) times smaller at theta = 0, 180 degrees (the ellipse's long axis) "
            "than at 90 on the hole, uniform on the outer circle (0: uniform)");
  param(P, "dalpha", p.dalpha).range(0, 45).help("clockwise rotation of the inner boundary per step (degrees)");
  param(P, "fem", p.fem).integer(0, 1)
      .help("1: finite element mode (the mesh moves with the nodes; mpType=1 only)");
  return P;
}

namespace {
constexpr double R = 10.0;
double holeA(const Doughnut& p) { return p.hole == 0 ? 5.0 : 6.0; }
double holeB(const Doughnut& p) { return p.hole == 0 ? 5.0 : 4.0; }
Eigen::Matrix2d rotation(double a) {
  Eigen::Matrix2d Q;
  Q << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return Q;
}
Eigen::MatrixX2d nodes0(const Doughnut& p) {  // node n = i nc + j
  const int nr = p.nr, nc = p.nc;
  Eigen::MatrixX2d X((nr + 1) * nc, 2);
  for (int i = 0; i <= nr; ++i)
    for (int j = 0; j < nc; ++j) {
      const double tau = 2 * M_PI * j / nc, s = double(i) / nr;
      const double t = tau - 0.5 * (1 - s) * p.refine * std::sin(2 * tau);  // graded at the hole
      X.row(i * nc + j) << (1 - s) * holeA(p) * std::cos(t) + s * R * std::cos(t),
          (1 - s) * holeB(p) * std::sin(t) + s * R * std::sin(t);
    }
  return X;
}
Eigen::MatrixXi cells(const Doughnut& p) {
  const int nr = p.nr, nc = p.nc;
  Eigen::MatrixXi T(nr * nc, 4);
  for (int i = 0; i < nr; ++i)
    for (int j = 0; j < nc; ++j)
      T.row(i * nc + j) << i * nc + j, (i + 1) * nc + j, (i + 1) * nc + (j + 1) % nc, i * nc + (j + 1) % nc;
  return T;
}
// the step's conditions: outer nodes fixed, inner nodes turned by dalpha clockwise
void conditions(Mesh& mesh, const Doughnut& p) {
  const int nr = p.nr, nc = p.nc;
  const Eigen::Matrix2d dQ = rotation(-p.dalpha * M_PI / 180) - Eigen::Matrix2d::Identity();
  mesh.bc.clear();
  for (int j = 0; j < nc; ++j) {
    const Vector2d du = dQ * mesh.coord.row(j).transpose();
    mesh.bc.insert(mesh.bc.end(), {{dof(j, 0), du(0)}, {dof(j, 1), du(1)},
                                   {dof(nr * nc + j, 0), 0.0}, {dof(nr * nc + j, 1), 0.0}});
  }
}
}  // namespace

Analysis setupGrid(const Doughnut& p) {
  Analysis an = baseAnalysis(p);
  an.fem = p.fem == 1;
  if (an.fem && p.mpType != MpType::MPM) throw InputError("fem=1 takes mpType=1 (MPM points)");
  const Eigen::MatrixX2d X0 = nodes0(p);
  const Eigen::MatrixXi T = cells(p);
  an.mesh = generalMesh(X0, T);
  conditions(an.mesh, p);
  fillCells(an.mpData, an.mesh, p, 0.0);
  const int nr = p.nr, nc = p.nc;
  const MpType type = p.mpType;
  for (int i = 0; i <= nr; ++i) {  // sampling points along theta = 0
    const Vector2d x = X0.row(i * nc).transpose();
    if (an.fem) { an.tagged.push_back(i * nc); continue; }                  // the node itself
    if (type != MpType::CPDI2 && (i == 0 || i == nr)) { an.tagged.push_back(-1 - i); continue; }  // prescribed
    if (type == MpType::CPDI2) {                                            // a corner on it
      for (size_t q = 0; q < an.mpData.size(); ++q)
        for (int c = 0; c < 4; ++c)
          if ((an.mpData[q].cpdi->xc.col(c) - x).norm() < 1e-9 * R && int(an.tagged.size()) == i)
            an.tagged.push_back(int(4 * q + c));
      continue;
    }
    MaterialPoint pt = an.mpData.front();                                   // extra point: a
    pt.mpC = pt.X0 = x;                                                     // square of edge 1e-3
    pt.vp = pt.vp0 = 1e-6;
    pt.mpM = 0.0;
    pt.lp = pt.lp0 = Vector2d::Constant(type == MpType::MPM ? 0.0 : 5e-4);
    if (pt.cpdi) pt.cpdi->st0 = pt.cpdi->st = 1e-3 * Eigen::Matrix2d::Identity();
    an.tagged.push_back(int(an.mpData.size()));
    an.mpData.push_back(pt);
  }
  const double dalpha = p.dalpha * M_PI / 180, C = 2 * M_PI * holeA(p), E = p.E;
  std::vector<int> inner(nc);
  for (int j = 0; j < nc; ++j) inner[j] = j;
  an.gridMoves = true;                                          // rotated each step (or fem)
  an.beforeStep = [=](Analysis& a, int lstp) {
    if (!a.fem) a.mesh = generalMesh((X0 * rotation(-(lstp - 1) * dalpha).transpose()).eval(), T);
    conditions(a.mesh, p);
  };
  const double a = holeA(p), b = holeB(p);  // the hole's perimeter (Ramanujan; 2 pi A for a circle)
  const double Ch = M_PI * (3 * (a + b) - std::sqrt((3 * a + b) * (a + 3 * b)));
  an.afterStep = [=](Analysis& a, int lstp, double /*lf: alpha = lstp x dalpha*/) {
    const double f = reactionOver(a.frct, inner).magnitudes;
    double torque = 0;  // clockwise moment of the inner nodes' reactions about the centre
    for (int j : inner) {
      const Vector2d x = a.mesh.coord.row(j).transpose() + (a.fem ? Vector2d::Zero() : Vector2d(a.uvw.segment<2>(dof(j, 0))));
      torque -= x(0) * a.frct(dof(j, 1)) - x(1) * a.frct(dof(j, 0));
    }
    a.history.push_back({{"lstp", lstp}, {"alpha", lstp * dalpha * 180 / M_PI}, {"f", f}, {"fNorm", f / (C * E)},
                         {"torque", torque}, {"torqueNorm", torque / (Ch * E)}});
  };
  return an;
}

Results results(const Analysis& an, const Doughnut& p) {
  Results r;
  if (!an.history.empty()) r.push_back({"fNorm", an.history.back()[3].second});
  const Eigen::MatrixX2d X0 = nodes0(p);
  const int nc = p.nc;
  for (size_t i = 0; i < an.tagged.size(); ++i) {
    const int k = an.tagged[i];
    Vector2d u;
    if (an.fem) u = (an.mesh.coord.row(k) - X0.row(k)).transpose();
    else if (k < 0)  // an end node: its prescribed displacement (inner: turned by alpha; outer: 0)
      u = k == -1 ? Vector2d((rotation(-p.dalpha * M_PI / 180 * an.history.size()) -
                              Eigen::Matrix2d::Identity()) * X0.row(0).transpose())
                  : Vector2d::Zero();
    else if (an.mpData.front().mpType == MpType::CPDI2)
      u = an.mpData[k / 4].cpdi->xc.col(k % 4) - X0.row(int(i) * nc).transpose();
    else u = an.mpData[k].u;
    r.push_back({"ux_" + std::to_string(i), u(0)});
    r.push_back({"uy_" + std::to_string(i), u(1)});
  }
  return r;
}

// this setup's line in the table of setups/setups.cpp
SetupCalls calls() { return {params, setupGrid, results}; }

}  // namespace ample::doughnut
