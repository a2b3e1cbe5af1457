//--------------------------------------------------------------------------
// ibStiffness — the implicit-boundary terms K2, K3 (eqs 17-27) and f_ER (eq 28)
//--------------------------------------------------------------------------
// See ibStiffness.h for the equations, inputs and outputs.
//--------------------------------------------------------------------------
#include "ibStiffness.h"
#include "dirichletBand.h"
#include "ample/errors.h"
#include <cmath>

namespace ample {

namespace {
using Mat38 = Eigen::Matrix<double, 3, 8>;

// n-point Gauss-Legendre rule on [0, 1] (Newton on the Legendre polynomial)
struct GaussRule { std::vector<double> x, w; };
GaussRule gaussRule(int n) {
  GaussRule g{std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
  std::vector<double>&x = g.x, &w = g.w;
  for (int i = 0; i < n; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = z;                         // P_0, P_1, ... P_n by recurrence
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1.0);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    x[i] = 0.5 * (1.0 - z);                                      // mapped to [0, 1]
    w[i] = 1.0 / ((1.0 - z * z) * dp * dp);
  }
  return g;
}

// strain [G_xx, G_yy, G_xy + G_yx] of the tensor G = v (x) g
Vector3d eps(const Vector2d& v, const Vector2d& g) {
  return Vector3d(v(0) * g(0), v(1) * g(1), v(0) * g(1) + v(1) * g(0));
}
}  // namespace

Matrix3d planeStrainC(double E, double nu) {
  const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  Matrix3d C;
  C << lam + 2 * mu, lam, 0, lam, lam + 2 * mu, 0, 0, 0, mu;
  return C;
}

Eigen::Matrix<double, 8, 8> ibCellStiffness(const Mesh& mesh, const Boundary& b, const CutCell& c,
                                            const Matrix3d& C) {
  const BoundaryType t = b.type[c.seg];
  const bool normalOnly = t == BoundaryType::Roller || t == BoundaryType::PrescribedNormal;
  const BandIntegrals bi = bandIntegrals(b.delta);
  const double dDp = b.coupling == IbCoupling::Paper ? bi.d_dp : bi.dp;  // 1/2 or 1
  const double len = (b.x[c.seg + 1] - b.x[c.seg]).norm() * (c.r1 - c.r0);
  const Vector2d x0 = mesh.coord.row(mesh.etpl(c.cell, 0)).transpose();
  const double ca[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};       // local corners (formCoord2D)
  static const GaussRule rule = gaussRule(10);                   // sec 4: 10 points along t, once
  const std::vector<double>&gx = rule.x, &gw = rule.w;
  Eigen::Matrix<double, 8, 8> K = Eigen::Matrix<double, 8, 8>::Zero();
  for (size_t q = 0; q < gx.size(); ++q) {
    const double r = c.r0 + gx[q] * (c.r1 - c.r0);
    const Vector2d xb = pointAt(b, c.seg, r), n = stiffnessNormal(b, c.seg, r);  // on the boundary
    const Eigen::Matrix2d M = normalOnly ? Eigen::Matrix2d(n * n.transpose())
                                         : Eigen::Matrix2d::Identity();
    const Eigen::Matrix2d A = Eigen::Matrix2d::Identity() - M;    // [D] = A + d M
    const Vector2d xi = (xb - x0).cwiseQuotient(mesh.h);
    Mat38 a, m, g;                                                // the columns a_jl, m_jl, g_jl
    for (int j = 0; j < nen; ++j) {
      const double fx = ca[j][0] * xi(0) + (1 - ca[j][0]) * (1 - xi(0));
      const double fy = ca[j][1] * xi(1) + (1 - ca[j][1]) * (1 - xi(1));
      const Vector2d dN((2 * ca[j][0] - 1) / mesh.h(0) * fy, (2 * ca[j][1] - 1) / mesh.h(1) * fx);
      for (int l = 0; l < nD; ++l) {
        a.col(2 * j + l) = eps(A.col(l), dN);                     // eq 19, free part
        m.col(2 * j + l) = eps(M.col(l), dN);                     // eq 19, times d
        g.col(2 * j + l) = eps(fx * fy * M.col(l), n);            // eq 20, times d'
      }
    }
    const Eigen::Matrix<double, 8, 8> K2 = (bi.dp * a + dDp * m).transpose() * C * g;  // 26
    const Eigen::Matrix<double, 8, 8> K3 = bi.dp_dp * g.transpose() * C * g;               // 27
    K += gw[q] * len * (K2 + K2.transpose() + K3);
  }
  return K;
}

ImplicitBoundaries ibStiffness(const Mesh& mesh, const std::vector<Boundary>& boundaries,
                               const std::vector<MaterialPoint>& mpData, int lstp, double share) {
  ImplicitBoundaries ib;
  if (boundaries.empty()) return ib;
  std::vector<Vector3d> cst(mesh.nels(), Vector3d::Zero());       // sum of E, nu; count
  for (const MaterialPoint& mp : mpData)
    for (int e = 0; e < mp.ne; ++e) cst[mp.eIN[e]] += Vector3d(mp.mCst.E, mp.mCst.nu, 1.0);
  std::vector<Eigen::Triplet<double>> trip;
  ib.f = Eigen::VectorXd::Zero(mesh.nDoF());
  for (size_t bi = 0; bi < boundaries.size(); ++bi) {
    const Boundary& b = boundaries[bi];
    const size_t before = ib.cells.size();
    for (const CutCell& c : cutCells(mesh, b)) {
      if (cst[c.cell](2) == 0) continue;                          // no point: nothing to hold
      const Vector3d m = cst[c.cell] / cst[c.cell](2);            // mean E, nu of its points
      IbCellTerm t{int(bi), {}, ibCellStiffness(mesh, b, c, planeStrainC(m(0), m(1))), {}};
      const BoundaryType type = b.type[c.seg];
      const bool prescribed = type == BoundaryType::Prescribed || type == BoundaryType::PrescribedNormal;
      const Vector2d ua = prescribed ? Vector2d(share * duAt(b, lstp)) : Vector2d::Zero();
      Eigen::Matrix<double, 8, 1> uae;                            // eq 28: u_a on the cell's dofs
      for (int j = 0; j < nen; ++j)
        for (int i = 0; i < nD; ++i) {
          t.dofs[2 * j + i] = dof(mesh.etpl(c.cell, j), i);
          uae(2 * j + i) = ua(i);
        }
      t.f = t.k * uae;
      for (int r = 0; r < 8; ++r) {
        ib.f(t.dofs[r]) += t.f(r);
        for (int q = 0; q < 8; ++q) trip.emplace_back(t.dofs[r], t.dofs[q], t.k(r, q));
      }
      ib.cells.push_back(t);
    }
    if (ib.cells.size() == before && !b.du.empty() && duAt(b, lstp).norm() > 0 && !mpData.empty())
      throw RunError("implicit boundary " + std::to_string(bi) + " (prescribed) cuts no cell that "
                     "holds a material point in load step " + std::to_string(lstp) + ": it lies "
                     "beyond the points nearest to it and would push nothing; use more points "
                     "per cell (mp) or another grid spacing h");
  }
  ib.K.resize(mesh.nDoF(), mesh.nDoF());
  ib.K.setFromTriplets(trip.begin(), trip.end());
  return ib;
}

Eigen::VectorXd addImplicitBoundaries(const ImplicitBoundaries& ib, const Eigen::VectorXd& uvw,
                                      SpMat& Kt, Eigen::VectorXd& fint) {
  if (ib.K.nonZeros() == 0) return Eigen::VectorXd::Zero(uvw.size());  // no implicit boundaries
  Kt = Kt + ib.K;                                                 // a linear penalty-like term
  const Eigen::VectorXd reaction = ib.f - ib.K * uvw;             // the boundaries' forces
  fint -= reaction;
  return reaction;
}

std::vector<Vector2d> boundaryForces(const ImplicitBoundaries& ib, const Eigen::VectorXd& uvw,
                                     int nBoundaries) {
  std::vector<Vector2d> F(nBoundaries, Vector2d::Zero());
  for (const IbCellTerm& t : ib.cells) {
    Eigen::Matrix<double, 8, 1> ue;
    for (int r = 0; r < 8; ++r) ue(r) = uvw(t.dofs[r]);
    const Eigen::Matrix<double, 8, 1> r = t.f - t.k * ue;
    for (int j = 0; j < nen; ++j) F[t.boundary] += Vector2d(r(2 * j), r(2 * j + 1));
  }
  return F;
}

void moveBoundaries(std::vector<Boundary>& boundaries, int lstp, double share) {
  for (Boundary& b : boundaries) {
    const Vector2d du = share * duAt(b, lstp);
    std::vector<char> moves(b.x.size(), 0);
    for (int s = 0; s < b.segments(); ++s)
      if (b.type[s] == BoundaryType::Prescribed || b.type[s] == BoundaryType::PrescribedNormal)
        moves[s] = moves[s + 1] = 1;
    for (size_t k = 0; k < b.x.size(); ++k)
      if (moves[k]) b.x[k] += du;
  }
}

}  // namespace ample
