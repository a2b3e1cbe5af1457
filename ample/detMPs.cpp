//--------------------------------------------------------------------------
// detMPs — internal force and stiffness of all material points (the point loop)
//--------------------------------------------------------------------------
// [AMPLE] eqs 5-18, 30-31; [Lagrangian] eqs 18-23 (PC); [Boundaries] eqs 2-3, 8-10
// (SS). See detMPs.h for the steps, inputs and outputs.
//--------------------------------------------------------------------------
#include "detMPs.h"
#include "constitutive/Hooke3d.h"
#include "constitutive/VMconst.h"
#include "ample/classroom/exercise.h"
#include "ample/stiffness/formPCstiff.h"
#include "ample/stiffness/formULstiff.h"
#include "ample/solver/stiffnessPattern.h"
#include "ample/solver/pointShares.h"
#include "ample/stiffness/tensorOps.h"
#include <algorithm>
#include <exception>

namespace ample {

namespace {

struct PointTerms {                          // what eqs 14 and 16 need of one point
  Eigen::Matrix4d A;                         // in-plane tangent, (i,j) -> 2i+j
  Eigen::Matrix2d Sf;                        // stress paired with dSx
  Eigen::Matrix<double, nD, MAXN> dSx;       // basis gradients
  double Vp;                                 // volume
};

// start + grad du, grad du = sum_v du_v (x) dS_v/dX~ (in-plane block): dF with
// start = I (eq 17); grad du itself with start = 0 (SS: no 1 + small - 1)
Matrix3d plusGradDu(Matrix3d start, const Eigen::VectorXd& uvw, const MaterialPoint& mp) {
  for (int v = 0; v < mp.nn; ++v)
    for (int i = 0; i < nD; ++i)
      for (int j = 0; j < nD; ++j) start(i, j) += uvw(dof(mp.nIN[v], i)) * mp.dSvp(j, v);
  return start;
}

ConstOut constitutive(const Vector6d& epsEtr, const MaterialPoint& mp) {  // cmType 1 or 2
  return (mp.cmType == CmType::Elastic) ? Hooke3d(epsEtr, mp.mCst) : VMconst(epsEtr, mp.mCst);
}

//--------------------------------------------------------------------------
// finiteStrainPoint — UL ([AMPLE] eqs 5-18) or PC ([Lagrangian] eqs 18-23)
//--------------------------------------------------------------------------
// Logarithmic elastic strain, Kirchhoff stress tau, sigma = tau / det(F).
// bEn = exp(2 eps_e,n) (eq 9) is that of the start of the step: elasticLeftCG
// computes it once per load step. Writes mp.F, mp.epsE, mp.sig (trial values
// until the step converges).
//--------------------------------------------------------------------------
PointTerms finiteStrainPoint(const Matrix3d& dF, const Matrix3d& bEn, Formulation form,
                             MaterialPoint& mp) {                // bEn = exp(2 eps_e,n), eq 9
  mp.F = dF * mp.Fn;                                            // eq 7
  const Matrix3d BeT = dF * bEn * dF.transpose();               // eq 8
  const InPlaneEigen eig = inPlaneEigen(BeT);                   // once for eq 10 and eq A.2
  const Vector6d epsEtr = tensorToStrain(0.5 * symLog(eig));    // eq 10

  const ConstOut cm = constitutive(epsEtr, mp);                 // eqs 5, 11
  mp.epsE = cm.epsE;
  mp.sig = cm.Ksig / mp.F.determinant();                        // eq 6

  PointTerms t;
  if (form == Formulation::UL) {                                // [AMPLE] eqs 14-18
    t.A = formULstiff2D(mp.F, cm.D, mp.sig, BeT, dLogdB2D(eig)); // [Lagrangian] eq A.1
    const Eigen::Matrix2d iF = dF.topLeftCorner<2, 2>().inverse();
    t.dSx.leftCols(mp.nn) = iF.transpose() * mp.dSvp.leftCols(mp.nn);  // eq 18: dS/dx
    t.Vp = dF.determinant() * mp.vp;                            // eq 15
    t.Sf = stressToTensor(mp.sig).topLeftCorner<2, 2>();
  } else {                                                      // [Lagrangian] eqs 18-23
    const double Jn = mp.Fn.determinant();
    const Matrix3d tau = stressToTensor(cm.Ksig);
    t.A = formPCstiff2D(dF, Jn, cm.D, tau, bEn, BeT);           // [Lagrangian] eq A.3
    t.dSx.leftCols(mp.nn) = mp.dSvp.leftCols(mp.nn);            // dS/dX~, no mapping
    t.Vp = mp.vp;                                               // V_p^n (eq 22)
    t.Sf = (tau * dF.inverse().transpose() / Jn).topLeftCorner<2, 2>();  // P~ (eq 18)
  }
  return t;
}

//--------------------------------------------------------------------------
// smallStrainPoint — infinitesimal strain, linear elasticity ([Boundaries] sec 2)
//--------------------------------------------------------------------------
// eps = eps_n + sym(grad du), grad du = sum_v du_v (x) dS_v/dX~ with the basis
// gradients of the start of the step ([Boundaries] eqs 2, 10); sigma = D eps (eq 3; cmType VM: the
// same radial return on the small strain); k_p = B' D B V_p, f_p = B' sigma V_p
// (eqs 8-9) with B, V_p those of the start of the step. F stays I (no
// configuration change), so V_p = det(F) V_p0 = V_p0 in updateMPs.
// Writes mp.F = I, mp.epsE, mp.sig (Cauchy).
//--------------------------------------------------------------------------
PointTerms smallStrainPoint(const Matrix3d& H, MaterialPoint& mp) {  // H = grad du
  const Vector6d epsTr = mp.epsEn + tensorToStrain(0.5 * (H + H.transpose()));  // eqs 2, 10

  const ConstOut cm = constitutive(epsTr, mp);                  // eq 3
  mp.F = Matrix3d::Identity();
  mp.epsE = cm.epsE;
  mp.sig = cm.Ksig;                                             // Cauchy stress

  PointTerms t;
  t.A = elasticBlock2D(cm.D);                                   // D (eq 8)
  t.dSx.leftCols(mp.nn) = mp.dSvp.leftCols(mp.nn);              // B: dS/dX~ (eq 6)
  t.Vp = mp.vp;                                                 // V_p = V_p0
  t.Sf = stressToTensor(mp.sig).topLeftCorner<2, 2>();          // sigma (eq 9)
  return t;
}

//--------------------------------------------------------------------------
// addPoint — f_p (eq 16) and k_p (eq 14) of one point, added into fint and the
// values Kval of Kt's pattern (eqs 30-31)
//--------------------------------------------------------------------------
// k_ab,ik = sum_jl dS_a/dx_j A_ijkl dS_b/dx_l V_p (eq 14) with the products
// g_jkl = dS_a/dx_j A_ijkl formed once per node a and direction i, not per b: half
// the multiplications, the same sums in the same order (bit for bit). Summing over
// j first (12 nn^2 flops) changes the round-off, enough to move where marginal runs stop.
// bEn: exp(2 eps_e,n) of this point (UL, PC; unused for SS).
//--------------------------------------------------------------------------
void addPoint(const Eigen::VectorXd& uvw, const Matrix3d& bEn, Formulation form, MaterialPoint& mp,
              Eigen::VectorXd& fint, PointStiffness& ke) {
  const PointTerms t =
      (form == Formulation::SS)
          ? smallStrainPoint(plusGradDu(Matrix3d::Zero(), uvw, mp), mp)                   // grad du
          : finiteStrainPoint(plusGradDu(Matrix3d::Identity(), uvw, mp), bEn, form, mp);  // dF, eq 17

  int d[nD * MAXN];                                             // the point's dofs, ascending
  for (int a = 0; a < mp.nn; ++a)
    for (int i = 0; i < nD; ++i) d[nD * a + i] = dof(mp.nIN[a], i);
  // BEGIN EXERCISE detMPs
  for (int a = 0; a < mp.nn; ++a)
    for (int i = 0; i < nD; ++i) {
      double fa = 0.0;                                          // eq 16
      for (int j = 0; j < nD; ++j) fa += t.dSx(j, a) * t.Sf(i, j);
      fint(d[nD * a + i]) += fa * t.Vp;
      double g[nD][nD][nD];                                     // g_jkl = dS_a/dx_j A_ijkl, once per a, i
      for (int j = 0; j < nD; ++j)
        for (int k = 0; k < nD; ++k)
          for (int l = 0; l < nD; ++l) g[j][k][l] = t.dSx(j, a) * t.A(2 * i + j, 2 * k + l);
      for (int b = 0; b < mp.nn; ++b)                           // eq 14
        for (int k = 0; k < nD; ++k) {
          double kab = 0.0;
          for (int j = 0; j < nD; ++j)
            for (int l = 0; l < nD; ++l) kab += g[j][k][l] * t.dSx(l, b);
          ke(nD * a + i, nD * b + k) = kab * t.Vp;
        }
    }
  // END EXERCISE
}

// k_p into the values Kval of Kt's pattern (eq 30), the columns of nodes [n0, n1) only
// (the serial loop: every node)
void assemble(const SpMat& pattern, bool blocked, const MaterialPoint& mp, const PointStiffness& ke,
              double* Kval, int n0, int n1) {
  const int ne = nD * mp.nn;
  if (blocked) return addNodeBlocks(pattern, Kval, mp.nIN.data(), mp.nn, ke.topLeftCorner(ne, ne), n0, n1);
  int d[nD * MAXN];                                             // the point's dofs, ascending
  for (int a = 0; a < mp.nn; ++a)
    for (int i = 0; i < nD; ++i) d[nD * a + i] = dof(mp.nIN[a], i);
  addToPattern(pattern, Kval, d, ne, ke.topLeftCorner(ne, ne), dof(n0, 0), dof(n1, 0));
}

// asks for memory the loop will read soon while this point is computed: the cache lines
// of the point after next (a MaterialPoint, sizeof 544) and the next point's slice of the
// basis arena (its nIN, Svp, dSvp: 28 B a node), whose place that point, fetched one
// turn earlier, now tells. Without it the loop waits for the first loads of each point
// (perf, at 1,088 B a point: a quarter of addPoint's time; collapse a = 8, detMPs 25-35 %
// faster with it, the same numbers)
void prefetchAhead(const std::vector<MaterialPoint>& mpData, int p, int end) {
#if defined(__GNUC__)
  auto lines = [](const void* first, size_t bytes) {  // every 64-byte line of these bytes
    const char* b = static_cast<const char*>(first);
    for (size_t k = 0; k < bytes; k += 64) __builtin_prefetch(b + k);
    if (bytes > 0) __builtin_prefetch(b + bytes - 1);    // the last, when they straddle one more
  };
  if (p + 2 < end) lines(&mpData[p + 2], sizeof(MaterialPoint));
  if (p + 1 < end) {
    const MaterialPoint& next = mpData[p + 1];
    lines(next.nIN.data(), next.nn * sizeof(int));
    lines(next.Svp.data(), next.nn * sizeof(double));
    lines(next.dSvp.data(), next.nn * nD * sizeof(double));
  }
#else
  (void)mpData, (void)p, (void)end;
#endif
}

// the point loop of detMPs on nt threads, each owning a range of nodes: thread t adds
// the f_p and k_p of every point that links one of its nodes, in point order, into its
// rows of fint and its columns of Kt. Each entry then gets the same terms in the same
// order as in the serial loop: the same numbers bit for bit, for any number of threads.
// A point whose nodes lie in two ranges is computed by both: its state (F, sig, epsE) is
// written by the owner of its first node, the other works on a copy taken before any
// point is computed. The ranges are cut so that each thread owns the first nodes of about
// np / nt points.
void detMPsOnThreads(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData, Formulation form,
                     int nt, DetMPsOut& out) {
  const int np = int(mpData.size()), nodes = int(uvw.size()) / nD;
  auto firstNode = [&](int p) { return mpData[p].nn > 0 ? mpData[p].nIN[0] : 0; };
  std::vector<int> cut(nt + 1, nodes);                          // thread t owns [cut[t], cut[t+1])
  std::vector<int> first(nodes + 1, 0);                         // points by their first node
  for (int p = 0; p < np; ++p) first[firstNode(p) + 1]++;
  cut[0] = 0;
  for (int n = 0, seen = 0, t = 1; n < nodes && t < nt; ++n) {
    seen += first[n + 1];
    while (t < nt && long(seen) * nt >= long(np) * t) cut[t++] = n + 1;
  }
  struct Share {
    std::vector<int> points;                                    // those linking its nodes, in order
    std::vector<MaterialPoint> copies;                          // of those it does not own
    Eigen::VectorXd fint;                                       // its rows are read
    int failedAt;                                               // the first point that threw
    std::exception_ptr failed;
  };
  std::vector<Share> share(nt);
  forPointShares(nt, nt, [&](int t, int, int) {                 // 1: the lists (mpData read only)
    Share& s = share[t];
    for (int p = 0; p < np; ++p) {
      const MaterialPoint& mp = mpData[p];
      const int* nIN = mp.nIN.data();
      const bool owner = firstNode(p) >= cut[t] && firstNode(p) < cut[t + 1];
      const bool links = mp.nn > 0 && nIN[mp.nn - 1] >= cut[t] && nIN[0] < cut[t + 1] &&
                         *std::lower_bound(nIN, nIN + mp.nn, cut[t]) < cut[t + 1];
      if (!owner && !links) continue;
      s.points.push_back(owner ? p : -1 - p);                   // -1 - p: work on a copy
      if (!owner) s.copies.push_back(mp);
    }
  });
  static const Matrix3d none = Matrix3d::Identity();
  forPointShares(nt, nt, [&](int t, int, int) {                 // 2: the points
    Share& s = share[t];
    const int n0 = cut[t], n1 = cut[t + 1];
    s.fint.setZero(uvw.size());
    s.failedAt = np;
    PointStiffness ke;
    for (size_t k = 0, c = 0; k < s.points.size(); ++k) {
      const int p = s.points[k] >= 0 ? s.points[k] : -1 - s.points[k];
      MaterialPoint& mp = s.points[k] >= 0 ? mpData[p] : s.copies[c++];
      prefetchAhead(mpData, p, np);                             // memory only: the next points
      try {
        addPoint(uvw, out.bEn.empty() ? none : out.bEn[p], form, mp, s.fint, ke);
      } catch (...) {
        s.failedAt = p, s.failed = std::current_exception();
        return;
      }
      assemble(out.Kt, out.blocked, mp, ke, out.Kt.valuePtr(), n0, n1);
    }
    const int r0 = dof(n0, 0), rows = dof(n1, 0) - r0;
    out.fint.segment(r0, rows) = s.fint.segment(r0, rows);
  });
  int t = 0;                                                    // the first failure in point order
  for (int u = 1; u < nt; ++u)
    if (share[u].failedAt < share[t].failedAt) t = u;
  if (share[t].failed) std::rethrow_exception(share[t].failed);
}

}  // namespace

// exp(2 eps_e,n) of every point (eq 9): it does not change within a load step
std::vector<Matrix3d> elasticLeftCG(const std::vector<MaterialPoint>& mpData) {
  const int np = int(mpData.size());
  std::vector<Matrix3d> bEn(np);
  forPointShares(np, pointThreads(np), [&](int, int begin, int end) {  // each point its own
    for (int p = begin; p < end; ++p) bEn[p] = symExp(2.0 * strainToTensor(mpData[p].epsEn));
  });
  return bEn;
}

void detMPs(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData, Formulation form,
            DetMPsOut& out) {
  const int nDoF = int(uvw.size()), np = int(mpData.size());
  if (out.Kt.rows() != nDoF || out.Kt.nonZeros() == 0) out.Kt = stiffnessPattern(nDoF, mpData);
  if (form != Formulation::SS && int(out.bEn.size()) != np) out.bEn = elasticLeftCG(mpData);
  if (out.blockedNnz != out.Kt.nonZeros()) {                    // a new pattern (or one grown by
    out.blocked = nodeBlocked(out.Kt);                          // the ghost penalty / IB terms)
    out.blockedNnz = out.Kt.nonZeros();
  }
  out.fint.setZero(nDoF);
  out.Kt.coeffs().setZero();                                    // the pattern's values only
  const int nt = pointThreads(np);
  if (nt > 1) return detMPsOnThreads(uvw, mpData, form, nt, out);  // the same sums, on nt threads
  static const Matrix3d none = Matrix3d::Identity();            // SS: no bEn
  PointStiffness ke;                                            // k_p (eq 14)
  for (int p = 0; p < np; ++p) {                                // the point loop
    prefetchAhead(mpData, p, np);                               // memory only: the next points
    MaterialPoint& mp = mpData[p];                              // the point (gdb: p mp)
    const Matrix3d& bEn = out.bEn.empty() ? none : out.bEn[p];
    addPoint(uvw, bEn, form, mp, out.fint, ke);                 // f_p into fint, k_p
    assemble(out.Kt, out.blocked, mp, ke, out.Kt.valuePtr(), 0, nDoF / nD);  // eq 30
  }
}

DetMPsOut detMPs(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData, Formulation form) {
  DetMPsOut out;
  detMPs(uvw, mpData, form, out);
  return out;
}

}  // namespace ample
