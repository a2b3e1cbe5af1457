//--------------------------------------------------------------------------
// setupHelpers — material point generation and boundary conditions for setups
//--------------------------------------------------------------------------
// See setupHelpers.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "setupHelpers.h"
#include "detMpPos.h"
#include "ample/errors.h"
#include "ample/solver/solverChoice.h"
#include "shapefunc.h"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace ample {

Analysis baseAnalysis(const Common& p) {
  Analysis an;
  an.lstps = p.lstps;
  an.tol = p.tol;
  an.NRitMax = p.NRitMax;
  an.solver = p.solver;
  if (an.solver != LinearSolver::LU) checkSolverBuilt(an.solver);  // one this build lacks: InputError
  an.substeps = p.substeps;
  an.ghost = p.ghost;
  an.split = p.split;
  an.lone = p.lone;
  an.formulation = p.formulation;
  an.domainUpdate = p.domainUpdate;
  an.locking = p.locking;
  an.geostatic = p.geostatic;
  an.K0 = p.K0;
  return an;
}

namespace {
// one point of fillBlock at x with domain half lengths lp0 (volume 4 lp0_x lp0_y)
MaterialPoint blockPoint(const Vector2d& x, const Vector2d& lp0, const Common& p, double rho) {
  MaterialPoint pt;
  pt.mpType = p.mpType;
  pt.cmType = p.cmType;
  pt.mpC = x;
  pt.X0 = pt.mpC;
  pt.lp0 = lp0;
  pt.vp0 = pt.vp = 4.0 * pt.lp0(0) * pt.lp0(1);
  if (isCPDI(pt)) {                                   // the domain of a CPDI point
    CpdiDomain d;
    d.st0 = d.st = (2.0 * pt.lp0).asDiagonal();       // CPDI1 domain vectors s, t
    for (int c = 0; c < 4; ++c)                       // rectangle corners (CPDI2)
      d.xc.col(c) = pt.mpC + Vector2d((c == 1 || c == 2) ? pt.lp0(0) : -pt.lp0(0),
                                      (c >= 2) ? pt.lp0(1) : -pt.lp0(1));
    pt.cpdi = d;
  }
  if (pt.mpType == MpType::MPM) pt.lp0.setZero();  // standard MPM carries no domain
  pt.lp = pt.lp0;
  pt.mpM = rho * pt.vp0;
  pt.mCst.E = p.E;                                 // the constants of Hooke3d and VMconst
  pt.mCst.nu = p.nu;
  pt.mCst.rhoY = p.rhoY;
  return pt;
}

// calls point(x, lp0) for the mp x mp points of every cell of the block, in fillBlock's order
void forBlockPoints(const Vector2d& corner, int nelsx, int nelsy, const Vector2d& h, int mp,
                    const std::function<void(const Vector2d& x, const Vector2d& lp0)>& point) {
  const Eigen::MatrixX2d mpPos = detMpPos(mp);
  for (int ey = 0; ey < nelsy; ++ey)
    for (int ex = 0; ex < nelsx; ++ex) {
      const Vector2d c0 = corner + Vector2d(ex * h(0), ey * h(1));  // cell lower-left corner
      Eigen::Matrix<double, 4, 2> eC;                              // cell corner coordinates
      eC << c0(0), c0(1), c0(0) + h(0), c0(1), c0(0) + h(0), c0(1) + h(1), c0(0), c0(1) + h(1);
      for (int q = 0; q < mpPos.rows(); ++q)
        point(Vector2d((shapefunc(mpPos.row(q).transpose()).transpose() * eC).transpose()),
              Vector2d(h / (2.0 * mp)));
    }
}
}  // namespace

// bytes this machine can still give (MemAvailable of /proc/meminfo; 0 when unknown)
static double availableBytes() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kB = 0;
  while (in >> key >> kB)
    if (key == "MemAvailable:") return kB * 1024;
    else in.ignore(256, '\n');
  return 0;
}

std::string number(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.6g", v);
  return s;
}

void checkPointMemory(size_t points) {
  const size_t perPoint = sizeof(MaterialPoint);                    // its basis inside
  const double need = double(points) * perPoint, have = availableBytes();
  if (have > 0 && need > have) {
    std::ostringstream msg;
    msg.precision(3);
    msg << "the run would need at least " << need / (1 << 30) << " GiB for its " << points
        << " material points (" << perPoint << " bytes each: the point with its basis, "
        << "before the stiffness and its factors), more than the " << have / (1 << 30)
        << " GiB this machine has available: use fewer points (mp, a, nelsy, h)";
    throw InputError(msg.str());
  }
}

void fillBlock(std::vector<MaterialPoint>& mpData, const Vector2d& corner, int nelsx, int nelsy,
               const Vector2d& h, const Common& p, double rho) {
  const int mp = p.mp;
  const size_t n = mpData.size() + size_t(nelsx) * nelsy * mp * mp;
  checkPointMemory(n);
  if (n > mpData.capacity()) mpData.reserve(std::max(n, 2 * mpData.capacity()));  // amortised
  forBlockPoints(corner, nelsx, nelsy, h, mp, [&](const Vector2d& x, const Vector2d& lp0) {
    mpData.push_back(blockPoint(x, lp0, p, rho));
  });
}

namespace {
double cross2(const Vector2d& a, const Vector2d& b) { return a(0) * b(1) - a(1) * b(0); }
// the bilinear map of quadrilateral X (corners as columns) at xi, and its det J
Vector2d quadMap(const Eigen::Matrix<double, 2, 4>& X, double xi, double eta, double* detJ) {
  static const double xa[4] = {-1, 1, 1, -1}, ea[4] = {-1, -1, 1, 1};
  Vector2d x = Vector2d::Zero(), dxi = x, deta = x;
  for (int a = 0; a < 4; ++a) {
    x += 0.25 * (1 + xa[a] * xi) * (1 + ea[a] * eta) * X.col(a);
    dxi += 0.25 * xa[a] * (1 + ea[a] * eta) * X.col(a);
    deta += 0.25 * ea[a] * (1 + xa[a] * xi) * X.col(a);
  }
  if (detJ) *detJ = cross2(dxi, deta);
  return x;
}
}  // namespace

MaterialPoint cellPoint(const Vector2d& x, double V, const Common& p, double rho) {
  MaterialPoint pt = blockPoint(x, Vector2d::Constant(0.5 * std::sqrt(V)), p, rho);
  pt.vp0 = pt.vp = V;
  pt.mpM = rho * V;
  return pt;
}

void fillCells(std::vector<MaterialPoint>& mpData, const Mesh& mesh, const Common& p, double rho,
               int triPoints) {
  const MpType type = p.mpType;
  if (mesh.regular()) throw InputError("fillCells: a general mesh (generalMesh) is needed");
  if (type == MpType::GIMP) throw InputError("mpType=2 (GIMP) needs the regular grid");
  if (triPoints != 1 && triPoints != 3) throw InputError("fillCells: triPoints 1 or 3");
  checkPointMemory(mpData.size() + size_t(mesh.nels()) * 4);
  for (int e = 0; e < mesh.nels(); ++e) {
    Eigen::Matrix<double, 2, 4> X = Eigen::Matrix<double, 2, 4>::Zero();
    for (int a = 0; a < mesh.cellNodes(); ++a) X.col(a) = mesh.coord.row(mesh.etpl(e, a)).transpose();
    if (mesh.cellNodes() == 3) {
      if (type != MpType::MPM) throw InputError("fillCells: triangles take standard MPM points only");
      const double A = 0.5 * cross2(X.col(1) - X.col(0), X.col(2) - X.col(0));
      if (triPoints == 1) mpData.push_back(cellPoint((X.col(0) + X.col(1) + X.col(2)) / 3, A, p, rho));
      else
        for (int a = 0; a < 3; ++a)
          mpData.push_back(cellPoint((2.0 / 3) * X.col(a) + (X.col((a + 1) % 3) + X.col((a + 2) % 3)) / 6,
                                     A / 3, p, rho));
      continue;
    }
    const double g = 1.0 / std::sqrt(3.0);
    for (int q = 0; q < 4; ++q) {                 // sub-cells / Gauss points: x fastest
      const double sx = (q == 1 || q == 3) ? 1 : -1, sy = q >= 2 ? 1 : -1;
      double detJ = 0;
      if (type == MpType::MPM) {
        const Vector2d x = quadMap(X, sx * g, sy * g, &detJ);
        mpData.push_back(cellPoint(x, detJ, p, rho));
        continue;
      }
      Eigen::Matrix<double, 2, 4> xc;             // the sub-cell's corners, anticlockwise
      const double x0 = sx < 0 ? -1 : 0, y0 = sy < 0 ? -1 : 0;
      xc.col(0) = quadMap(X, x0, y0, nullptr);
      xc.col(1) = quadMap(X, x0 + 1, y0, nullptr);
      xc.col(2) = quadMap(X, x0 + 1, y0 + 1, nullptr);
      xc.col(3) = quadMap(X, x0, y0 + 1, nullptr);
      MaterialPoint pt = cellPoint(quadMap(X, x0 + 0.5, y0 + 0.5, nullptr),
                                   0.5 * std::abs(cross2(xc.col(2) - xc.col(0), xc.col(3) - xc.col(1))), p, rho);
      pt.cpdi->xc = xc;                           // type CPDI1 or CPDI2: cellPoint gave a domain
      pt.cpdi->st0.col(0) = 0.5 * (xc.col(1) - xc.col(0) + xc.col(2) - xc.col(3));
      pt.cpdi->st0.col(1) = 0.5 * (xc.col(3) - xc.col(0) + xc.col(2) - xc.col(1));
      pt.cpdi->st = pt.cpdi->st0;
      mpData.push_back(pt);
    }
  }
}

Reaction reactionOver(const Eigen::VectorXd& frct, const std::vector<int>& nodes) {
  Reaction r;
  for (int n : nodes) {
    if (n < 0 || dof(n, 1) >= frct.size())
      throw InputError("reactionOver: node " + std::to_string(n) + " outside [0, " +
                       std::to_string(frct.size() / nD - 1) + "]");
    const Vector2d f(frct(dof(n, 0)), frct(dof(n, 1)));
    r.sum += f;
    r.magnitudes += f.norm();
  }
  return r;
}

Boundary& addBoundary(Analysis& an, std::vector<Vector2d> x, std::vector<BoundaryType> type,
                      double deltaOverH, SolidSide solid) {
  if (x.size() < 2) throw InputError("addBoundary: a boundary needs at least two points");
  if (type.size() != x.size() - 1)
    throw InputError("addBoundary: one type per segment (" + std::to_string(x.size() - 1) +
                     " segments, " + std::to_string(type.size()) + " types)");
  const double h = an.mesh.h.minCoeff();
  if (!(h > 0)) throw InputError("addBoundary: make the mesh first (delta = deltaOverH h)");
  for (size_t s = 0; s + 1 < x.size(); ++s)
    if ((x[s + 1] - x[s]).norm() <= 1e-12 * h)
      throw InputError("addBoundary: segment " + std::to_string(s) + " has zero length");
  Boundary b;
  b.x = std::move(x);
  b.type = std::move(type);
  b.solid = solid;
  b.delta = deltaOverH * h;
  editBoundaries(an).push_back(std::move(b));
  return editBoundaries(an).back();
}

Boundary& addBoundary(Analysis& an, std::vector<Vector2d> x, BoundaryType type,
                      double deltaOverH, SolidSide solid) {
  const size_t nSeg = x.size() < 2 ? 0 : x.size() - 1;
  return addBoundary(an, std::move(x), std::vector<BoundaryType>(nSeg, type), deltaOverH, solid);
}

Eigen::Matrix2d rotationDegrees(double theta) {
  double c = std::cos(theta * M_PI / 180), s = std::sin(theta * M_PI / 180);
  if (std::fmod(theta, 90.0) == 0.0) c = std::round(c), s = std::round(s);
  Eigen::Matrix2d R;
  R << c, -s, s, c;
  return R;
}

Params ibCommonParams(IbCommon& p) {
  Params P = commonParams(p);
  param(P, "delta", p.delta).range(1e-12, 0.5).help("band width of eq 16 as a fraction of h");
  param(P, "ibK2", p.ibK2).choice(0, {"paper", "consistent"})
      .help("K2's inner integral over the d entries of [D1bar]: consistent = 1 (exact for "
            "linear fields; reproduces the paper's table I and fig 16), paper = int d d' = "
            "1/2 (eqs 21, 26 as printed: shifts each boundary by 3 delta / 8)");
  return P;
}

void ibSettings(Analysis& an, const IbCommon& p) {
  for (Boundary& b : editBoundaries(an)) b.coupling = p.ibK2;
}

Polygon solidPolygon(const std::vector<Boundary>& boundaries) {
  Polygon poly;
  for (const Boundary& b : boundaries)
    for (const Vector2d& p : b.x)
      if (poly.empty() || (p - poly.back()).norm() > 0.0) poly.push_back(p);  // joints once
  if (poly.size() > 1 && poly.front() == poly.back()) poly.pop_back();  // closed: not twice
  return poly;
}

void fillPolygon(std::vector<MaterialPoint>& mpData, const Vector2d& corner, int nelsx,
                 int nelsy, const Vector2d& h, const Common& p, double rho,
                 const Polygon& solid) {
  constexpr double full = 1.0 - 1e-12, none = 1e-12;  // fractions of the domain inside
  const int mp = p.mp;
  checkPointMemory(mpData.size() + size_t(nelsx) * nelsy * mp * mp);  // at most
  forBlockPoints(corner, nelsx, nelsy, h, mp, [&](const Vector2d& x, const Vector2d& lp0) {
    Polygon local = solid;  // the solid about the point: the area keeps its digits
    for (Vector2d& q : local) q -= x;
    const Polygon square = {{-lp0(0), -lp0(1)}, {lp0(0), -lp0(1)}, {lp0(0), lp0(1)},
                            {-lp0(0), lp0(1)}};
    const AreaCentroid in = polygonArea(clipPolygon(local, square));
    const double A = 4.0 * lp0(0) * lp0(1), frac = std::abs(in.area) / A;
    if (frac <= none) return;  // wholly outside: removed
    if (frac >= full) {        // wholly inside: fillBlock's point
      mpData.push_back(blockPoint(x, lp0, p, rho));
      return;
    }
    // truncated: at the centroid of the part inside, half lengths scaled to its area
    MaterialPoint pt = blockPoint(x + in.centroid, lp0 * std::sqrt(frac), p, rho);
    pt.vp0 = pt.vp = frac * A;  // the area inside the solid
    pt.mpM = rho * pt.vp0;
    mpData.push_back(pt);
  });
}

void fixDofs(Mesh& mesh, int i, const std::function<bool(double, double)>& where,
             double value) {
  for (int n = 0; n < mesh.nodes(); ++n)
    if (where(mesh.coord(n, 0), mesh.coord(n, 1))) mesh.bc.push_back({dof(n, i), value});
}

}  // namespace ample
