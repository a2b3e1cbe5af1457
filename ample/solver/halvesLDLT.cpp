//--------------------------------------------------------------------------
// halvesLDLT — LDL^T of Kt(fd,fd) as two halves and the interface between them
//--------------------------------------------------------------------------
// See halvesLDLT.h for the method, inputs and outputs.
//--------------------------------------------------------------------------
#include "halvesLDLT.h"
#include <Eigen/OrderingMethods>
#include <algorithm>
#include <climits>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace ample {

// breadth-first levels of K's graph from dof `start` (level -1: not reached); the dofs in visit order
static std::vector<int> levelsFrom(const SpMat& K, int start, std::vector<int>& level) {
  level.assign(K.rows(), -1);
  level[start] = 0;
  std::vector<int> queue{start};
  for (size_t h = 0; h < queue.size(); ++h)
    for (SpMat::InnerIterator it(K, queue[h]); it; ++it)
      if (level[it.row()] < 0) {
        level[it.row()] = level[queue[h]] + 1;
        queue.push_back(int(it.row()));
      }
  return queue;
}

// by position: the dofs below the median along the longer extent, and the rest; the interface is
// the smaller of the two sides' sets of dofs with a neighbour on the other side
static std::array<std::vector<int>, 3> splitAt(const SpMat& K, const std::vector<Eigen::Vector2d>& at) {
  const int n = int(K.rows());
  Eigen::Vector2d lo = at[0], hi = at[0];
  for (const Eigen::Vector2d& x : at) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  const int axis = hi(0) - lo(0) >= hi(1) - lo(1) ? 0 : 1;
  std::vector<double> c(n);
  for (int v = 0; v < n; ++v) c[v] = at[v](axis);
  std::vector<double> sorted = c;
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
  std::vector<int> side(n), touches(n, 0), touching{0, 0};
  for (int v = 0; v < n; ++v) side[v] = c[v] >= sorted[n / 2];
  for (int v = 0; v < n; ++v) {
    for (SpMat::InnerIterator it(K, v); it; ++it) touches[v] |= side[it.row()] != side[v];
    touching[side[v]] += touches[v];
  }
  const int t = touching[1] < touching[0] ? 1 : 0;     // the side whose border is the interface
  std::array<std::vector<int>, 3> split;
  for (int v = 0; v < n; ++v) split[side[v] == t && touches[v] ? 2 : side[v]].push_back(v);
  return split;
}

std::array<std::vector<int>, 3> splitInTwo(const SpMat& K, const std::vector<Eigen::Vector2d>& at) {
  const int n = int(K.rows());
  std::array<std::vector<int>, 3> split;
  if (n == 0) return split;
  if (int(at.size()) == n) return splitAt(K, at);
  std::vector<int> level;
  int start = 0, depth = -1;                            // a pseudo-peripheral start: restart from the
  for (int tries = 0; tries < 8; ++tries) {             // farthest dof while that deepens the levels
    const int last = levelsFrom(K, start, level).back();
    if (level[last] <= depth) break;
    depth = level[last];
    start = last;
  }
  depth = level[levelsFrom(K, start, level).back()];
  std::vector<int> count(depth + 1, 0);
  for (int v = 0; v < n; ++v)
    if (level[v] >= 0) count[level[v]]++;
  long best = LONG_MAX;                                 // the interface: a level inside, fewest of
  int cut = -1, before = 0;                             // max(before, after) + its own dofs
  for (int l = 1; l < depth; ++l) {
    before += count[l - 1];
    const long cost = long(std::max(before, n - before - count[l])) + count[l];
    if (cost < best) best = cost, cut = l;
  }
  for (int v = 0; v < n; ++v)                           // no level inside (a tiny or dense K): all in
    if (cut < 0) split[level[v] < 0 ? 1 : 0].push_back(v);   // half 1, the unreached in half 2
    else split[level[v] < 0 || level[v] > cut ? 1 : level[v] < cut ? 0 : 2].push_back(v);
  return split;
}

// K(dofs, dofs) in the order of dofs, its upper triangle if `upper`; value e is K's value fromK[e]
static SpMat principal(const SpMat& K, const std::vector<int>& dofs, bool upper, std::vector<int>& fromK) {
  std::vector<int> local(K.rows(), -1);
  for (size_t k = 0; k < dofs.size(); ++k) local[dofs[k]] = int(k);
  const int m = int(dofs.size());
  SpMat A(m, m);
  std::vector<std::pair<int, int>> column;              // (local row, value of K)
  fromK.clear();
  for (int c = 0; c < m; ++c) {
    column.clear();
    for (int e = K.outerIndexPtr()[dofs[c]]; e < K.outerIndexPtr()[dofs[c] + 1]; ++e) {
      const int r = local[K.innerIndexPtr()[e]];
      if (r >= 0 && (!upper || r <= c)) column.emplace_back(r, e);
    }
    std::sort(column.begin(), column.end());
    A.startVec(c);
    for (const auto& [r, e] : column) {
      A.insertBack(r, c) = K.valuePtr()[e];
      fromK.push_back(e);
    }
  }
  A.finalize();
  return A;
}

// the loops over the two halves: on two threads where there are two (the same arithmetic
// either way); without OpenMP one after the other
#ifdef _OPENMP
static int halvesThreads() { return std::min(2, omp_get_max_threads()); }
#define EACH_HALF_ON_ITS_THREAD _Pragma("omp parallel for num_threads(halvesThreads()) schedule(static, 1)")
#else
#define EACH_HALF_ON_ITS_THREAD
#endif

void HalvesLDLT::analyzePattern(const SpMat& K, const std::vector<Eigen::Vector2d>& at) {
  eigen_assert(K.isCompressed() && K.rows() == K.cols());
  const std::array<std::vector<int>, 3> split = splitInTwo(K, at);
  interface_ = split[2];
EACH_HALF_ON_ITS_THREAD
  for (int i = 0; i < 2; ++i) {                         // each half on its own thread
    Half& h = half_[i];
    h.n = int(split[i].size());
    std::vector<int> unused;
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> amd;   // the interior by AMD
    if (h.n > 0) Eigen::AMDOrdering<int>()(principal(K, split[i], false, unused), amd);
    h.dofs.resize(h.n);
    for (int k = 0; k < h.n; ++k) h.dofs[k] = split[i][amd.indices()[k]];
    h.dofs.insert(h.dofs.end(), interface_.begin(), interface_.end());
    h.K = principal(K, h.dofs, true, h.fromK);
    if (!h.dofs.empty()) h.ldlt.analyzePattern(h.K);
  }
  std::vector<int> local(K.rows(), -1);                 // A_ss: where its values sit in K
  for (size_t k = 0; k < interface_.size(); ++k) local[interface_[k]] = int(k);
  fromKss_.clear();
  for (size_t c = 0; c < interface_.size(); ++c)
    for (int e = K.outerIndexPtr()[interface_[c]]; e < K.outerIndexPtr()[interface_[c] + 1]; ++e)
      if (local[K.innerIndexPtr()[e]] >= 0) fromKss_.push_back({local[K.innerIndexPtr()[e]], int(c), e});
  info_ = Eigen::InvalidInput;                          // analysed, not factorised
}

// L_i D_i L_i^T of half h, and T_i = L_ss D_ss L_ss^T from its interface columns
void HalvesLDLT::factorizeHalf(Half& h) {
  const int s = int(interface_.size());
  h.T.setZero(s, s);
  if (h.dofs.empty()) return;
  h.ldlt.factorize(h.K);
  if (h.ldlt.info() != Eigen::Success || s == 0) return;  // (no interface: T_i is empty)
  const SpMat& L = h.ldlt.matrixL().nestedExpression();
  Eigen::MatrixXd Lss = Eigen::MatrixXd::Identity(s, s);
  for (int c = h.n; c < h.n + s; ++c)
    for (SpMat::InnerIterator it(L, c); it; ++it)
      if (it.row() > c) Lss(it.row() - h.n, c - h.n) = it.value();
  const Eigen::MatrixXd DLt = h.ldlt.vectorD().tail(s).asDiagonal() * Lss.transpose();
  h.T.noalias() = Lss.triangularView<Eigen::UnitLower>() * DLt;
}

void HalvesLDLT::factorize(const SpMat& K) {
  for (Half& h : half_)
    for (size_t e = 0; e < h.fromK.size(); ++e) h.K.valuePtr()[e] = K.valuePtr()[h.fromK[e]];
EACH_HALF_ON_ITS_THREAD
  for (int i = 0; i < 2; ++i) factorizeHalf(half_[i]);
  info_ = Eigen::Success;
  for (const Half& h : half_)
    if (!h.dofs.empty() && h.ldlt.info() != Eigen::Success) info_ = Eigen::NumericalIssue;
  if (info_ != Eigen::Success || interface_.empty()) return;
  Eigen::MatrixXd S = half_[0].T + half_[1].T;          // S = T_1 + T_2 - A_ss
  for (const auto& [r, c, e] : fromKss_) S(r, c) -= K.valuePtr()[e];
  S_.compute(S);
  if (S_.info() != Eigen::Success || !S_.vectorD().allFinite() || (S_.vectorD().array() == 0).any())
    info_ = Eigen::NumericalIssue;
}

// y = L_i^-1 b through the interior columns: v (interior) becomes y, g (interface) gets -M_i y
void HalvesLDLT::forward(const Half& h, Eigen::VectorXd& v, Eigen::VectorXd& g) const {
  if (h.n == 0) return;                                 // (an empty half has no factor)
  const SpMat& L = h.ldlt.matrixL().nestedExpression();
  for (int j = 0; j < h.n; ++j)
    for (SpMat::InnerIterator it(L, j); it; ++it) {
      const int r = int(it.row());
      if (r <= j) continue;
      (r < h.n ? v(r) : g(r - h.n)) -= it.value() * v(j);
    }
}

// x = L_i^-T (D_i^-1 y - M_i^T x_s) through the interior columns, the interface's x_s known
void HalvesLDLT::backward(const Half& h, Eigen::VectorXd& v, const Eigen::VectorXd& xs) const {
  if (h.n == 0) return;
  const SpMat& L = h.ldlt.matrixL().nestedExpression();
  const Eigen::VectorXd& D = h.ldlt.vectorD();
  for (int j = h.n - 1; j >= 0; --j) {
    double x = v(j) / D(j);
    for (SpMat::InnerIterator it(L, j); it; ++it)
      if (it.row() > j) x -= it.value() * (it.row() < h.n ? v(it.row()) : xs(it.row() - h.n));
    v(j) = x;
  }
}

Eigen::VectorXd HalvesLDLT::solve(const Eigen::VectorXd& b) const {
  const int s = int(interface_.size());
  std::array<Eigen::VectorXd, 2> v, g;
  Eigen::VectorXd x(b.size()), xs(s);
EACH_HALF_ON_ITS_THREAD
  for (int i = 0; i < 2; ++i) {
    v[i].resize(half_[i].n);
    for (int k = 0; k < half_[i].n; ++k) v[i](k) = b(half_[i].dofs[k]);
    g[i].setZero(s);
    forward(half_[i], v[i], g[i]);
  }
  for (int k = 0; k < s; ++k) xs(k) = b(interface_[k]) + g[0](k) + g[1](k);
  if (s > 0) xs = S_.solve(xs);
EACH_HALF_ON_ITS_THREAD
  for (int i = 0; i < 2; ++i) {
    backward(half_[i], v[i], xs);
    for (int k = 0; k < half_[i].n; ++k) x(half_[i].dofs[k]) = v[i](k);
  }
  for (int k = 0; k < s; ++k) x(interface_[k]) = xs(k);
  return x;
}

}  // namespace ample
