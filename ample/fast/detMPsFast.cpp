//--------------------------------------------------------------------------
// detMPsFast — the point loop of an optimised build: the same equations, faster
//--------------------------------------------------------------------------
// See detMPsFast.h.
//--------------------------------------------------------------------------
#include "detMPsFast.h"
#include "addPoint.h"
#include "ample/formulations/detMPsForm.h"
#include "ample/solver/pointShares.h"
#include "ample/solver/stiffnessPattern.h"
#include <algorithm>
#include <exception>

namespace ample {

namespace {

// k_p of point p into the values Kval of Kt's pattern (eq 30), the columns of nodes [n0, n1)
// only (the serial loop: every node)
void assembleNodes(const SpMat& pattern, const PointLoopPlan& plan, int p, const MaterialPoint& mp,
                   const PointStiffness& ke, double* Kval, int n0, int n1) {
  const int ne = nD * mp.nn;
  if (plan.blocked)
    return addNodeBlocks(pattern, Kval, mp.nIN.data(), mp.nn, plan.at.data() + plan.from[p],
                         ke.topLeftCorner(ne, ne), n0, n1);
  int d[nD * MAXN];                                             // the point's dofs, ascending
  for (int a = 0; a < mp.nn; ++a)
    for (int i = 0; i < nD; ++i) d[nD * a + i] = dof(mp.nIN[a], i);
  addToPattern(pattern, Kval, d, ne, ke.topLeftCorner(ne, ne), dof(n0, 0), dof(n1, 0));
}

// asks for memory the loop will read soon while this point is computed: the cache lines
// of the point after next (a MaterialPoint with its basis). Without it the loop waits for
// the first loads of each point (perf, at 1,088 B a point: a quarter of addPoint's time;
// collapse a = 8, detMPs 25-35 % faster with it, the same numbers)
void prefetchAhead(const std::vector<MaterialPoint>& mpData, int p, int end) {
#if defined(__GNUC__)
  auto lines = [](const void* first, size_t bytes) {  // every 64-byte line of these bytes
    const char* b = static_cast<const char*>(first);
    for (size_t k = 0; k < bytes; k += 64) __builtin_prefetch(b + k);
    if (bytes > 0) __builtin_prefetch(b + bytes - 1);    // the last, when they straddle one more
  };
  if (p + 2 < end) lines(&mpData[p + 2], sizeof(MaterialPoint));
#else
  (void)mpData, (void)p, (void)end;
#endif
}

}  // namespace

struct ThreadShares {                                           // the threads' points, for a load step
  int np = 0, nt = 0;
  std::vector<int> cut;                                         // thread t owns nodes [cut[t], cut[t+1])
  struct Share {
    std::vector<int> points;                                    // those linking its nodes, in order
    std::vector<MaterialPoint> copies;                          // of those it does not own
    Eigen::VectorXd fint;                                       // its rows are read
    int failedAt;                                               // the first point that threw
    std::exception_ptr failed;
  };
  std::vector<Share> share;
};

namespace {

// where each point's 2 x 2 node blocks sit in a node-blocked Kt, once per pattern; a point
// that links the nodes of the one before it (most neighbours in a cell) shares its entries
void findBlocks(const SpMat& Kt, const std::vector<MaterialPoint>& mpData, PointLoopPlan& plan) {
  const int np = int(mpData.size());
  plan.from.assign(np + 1, 0);
  std::vector<char> shared(np, 0);                              // links the nodes of point p - 1
  long size = 0;
  for (int p = 0; p < np; ++p) {
    shared[p] = p > 0 && sameNodes(mpData[p], mpData[p - 1]);
    plan.from[p] = shared[p] ? plan.from[p - 1] : size;
    if (!shared[p]) size += long(mpData[p].nn) * mpData[p].nn;
  }
  plan.from[np] = size;
  plan.at.resize(size);
  forPointShares(np, pointThreads(np), [&](int, int begin, int end) {  // each point its own
    for (int p = begin; p < end; ++p)
      if (!shared[p])
        nodeBlockPositions(Kt, mpData[p].nIN.data(), mpData[p].nn, plan.at.data() + plan.from[p]);
  });
}

// the threads' node ranges and their points, once per load step (the points link the same
// nodes, and a copy's inputs, Fn, eps_e,n, the basis, do not change within a step)
void shareOut(const std::vector<MaterialPoint>& mpData, int nodes, int nt, ThreadShares& S) {
  const int np = int(mpData.size());
  auto firstNode = [&](int p) { return mpData[p].nn > 0 ? mpData[p].nIN[0] : 0; };
  S.np = np, S.nt = nt;
  S.cut.assign(nt + 1, nodes);
  std::vector<int> first(nodes + 1, 0);                         // points by their first node
  for (int p = 0; p < np; ++p) first[firstNode(p) + 1]++;
  S.cut[0] = 0;
  for (int n = 0, seen = 0, t = 1; n < nodes && t < nt; ++n) {
    seen += first[n + 1];
    while (t < nt && long(seen) * nt >= long(np) * t) S.cut[t++] = n + 1;
  }
  S.share.assign(nt, {});
  forPointShares(nt, nt, [&](int t, int, int) {                 // mpData read only
    ThreadShares::Share& s = S.share[t];
    s.points.reserve(np / nt + np / 16);
    for (int p = 0; p < np; ++p) {
      const MaterialPoint& mp = mpData[p];
      const int* nIN = mp.nIN.data();
      const bool owner = firstNode(p) >= S.cut[t] && firstNode(p) < S.cut[t + 1];
      const bool links = mp.nn > 0 && nIN[mp.nn - 1] >= S.cut[t] && nIN[0] < S.cut[t + 1] &&
                         *std::lower_bound(nIN, nIN + mp.nn, S.cut[t]) < S.cut[t + 1];
      if (!owner && !links) continue;
      s.points.push_back(owner ? p : -1 - p);                   // -1 - p: work on a copy
      if (!owner) s.copies.push_back(mp);
    }
  });
}

// the point loop of detMPs on nt threads, each owning a range of nodes: thread t adds
// the f_p and k_p of every point that links one of its nodes, in point order, into its
// rows of fint and its columns of Kt. Each entry then gets the same terms in the same
// order as in the serial loop: the same numbers bit for bit, for any number of threads.
// A point whose nodes lie in two ranges is computed by both: its state (F, sig, epsE) is
// written by the owner of its first node, the other works on a copy taken at the start
// of the step. The ranges are cut so that each thread owns the first nodes of about
// np / nt points.
void detMPsOnThreads(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData, Formulation form,
                     int nt, DetMPsOut& out) {
  const int np = int(mpData.size());
  PointLoopPlan& plan = *out.plan;
  if (!plan.threads || plan.threads->np != np || plan.threads->nt != nt) {
    plan.threads = std::make_shared<ThreadShares>();
    shareOut(mpData, int(uvw.size()) / nD, nt, *plan.threads);
  }
  const std::vector<int>& cut = plan.threads->cut;
  std::vector<ThreadShares::Share>& share = plan.threads->share;
  static const Matrix3d none = Matrix3d::Identity();
  forPointShares(nt, nt, [&](int t, int, int) {                 // the points
    ThreadShares::Share& s = share[t];
    const int n0 = cut[t], n1 = cut[t + 1];
    s.fint.setZero(uvw.size());
    s.failedAt = np;
    s.failed = nullptr;
    PointStiffness ke;
    for (size_t k = 0, c = 0; k < s.points.size(); ++k) {
      const int p = s.points[k] >= 0 ? s.points[k] : -1 - s.points[k];
      MaterialPoint& mp = s.points[k] >= 0 ? mpData[p] : s.copies[c++];
      prefetchAhead(mpData, p, np);                             // memory only: the next points
      try {
        addPoint(uvw, plan.bEn.empty() ? none : plan.bEn[p], form, mp, s.fint, ke);
      } catch (...) {
        s.failedAt = p, s.failed = std::current_exception();
        return;
      }
      assembleNodes(out.Kt, plan, p, mp, ke, out.Kt.valuePtr(), n0, n1);
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
std::vector<Matrix3d> elasticLeftCGs(const std::vector<MaterialPoint>& mpData) {
  const int np = int(mpData.size());
  std::vector<Matrix3d> bEn(np);
  forPointShares(np, pointThreads(np), [&](int, int begin, int end) {  // each point its own
    for (int p = begin; p < end; ++p) bEn[p] = elasticLeftCG(mpData[p]);
  });
  return bEn;
}

void detMPsFast(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData, Formulation form,
                DetMPsOut& out) {
  const int nDoF = int(uvw.size()), np = int(mpData.size());
  if (np < fastFrom()) return pointLoopOf(form)(uvw, mpData, form, out);  // small: the plain loop
  if (out.Kt.rows() != nDoF || out.Kt.nonZeros() == 0) out.Kt = stiffnessPattern(nDoF, mpData);
  if (!out.plan) out.plan = std::make_shared<PointLoopPlan>();
  PointLoopPlan& plan = *out.plan;
  if (form != Formulation::SS && int(plan.bEn.size()) != np) plan.bEn = elasticLeftCGs(mpData);
  if (plan.patternNnz != out.Kt.nonZeros()) {                   // a new pattern (or one grown by
    plan.blocked = nodeBlocked(out.Kt);                         // the ghost penalty / IB terms)
    plan.patternNnz = out.Kt.nonZeros();
    plan.at.clear(), plan.from.clear();
    if (plan.blocked) findBlocks(out.Kt, mpData, plan);
  }
  out.fint.setZero(nDoF);
  out.Kt.coeffs().setZero();
  const int nt = pointThreads(np);
  if (nt > 1) return detMPsOnThreads(uvw, mpData, form, nt, out);  // the same sums, on nt threads
  static const Matrix3d none = Matrix3d::Identity();            // SS: no bEn
  PointStiffness ke;
  for (int p = 0; p < np; ++p) {
    prefetchAhead(mpData, p, np);                               // memory only: the next points
    MaterialPoint& mp = mpData[p];
    addPoint(uvw, plan.bEn.empty() ? none : plan.bEn[p], form, mp, out.fint, ke);
    assembleNodes(out.Kt, plan, p, mp, ke, out.Kt.valuePtr(), 0, nDoF / nD);
  }
}

}  // namespace ample
