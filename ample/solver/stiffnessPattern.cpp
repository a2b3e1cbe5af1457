//--------------------------------------------------------------------------
// stiffnessPattern — the sparsity of Kt for one load step
//--------------------------------------------------------------------------
// [AMPLE] eq 30. See stiffnessPattern.h for what it saves, inputs and outputs.
//--------------------------------------------------------------------------
#include "stiffnessPattern.h"
#include <algorithm>

namespace ample {

bool sameNodes(const MaterialPoint& a, const MaterialPoint& b) {
  return a.nn == b.nn && std::equal(a.nIN.begin(), a.nIN.begin() + a.nn, b.nIN.begin());
}

SpMat stiffnessPattern(int nDoF, const std::vector<MaterialPoint>& mpData) {
  const int nodes = nDoF / nD;
  std::vector<int> linking;              // the points, less one that links the nodes of the one
  for (int p = 0; p < int(mpData.size()); ++p)  // before it (neighbours in a cell): no new pair
    if (p == 0 || !sameNodes(mpData[p], mpData[p - 1])) linking.push_back(p);
  std::vector<int> start(nodes + 1, 0);  // those points of each node, bucketed
  for (int p : linking)
    for (int b = 0; b < mpData[p].nn; ++b) start[mpData[p].nIN[b] + 1]++;
  for (int n = 0; n < nodes; ++n) start[n + 1] += start[n];
  std::vector<int> points(start[nodes]), fill(start.begin(), start.end() - 1);
  for (int p : linking)
    for (int b = 0; b < mpData[p].nn; ++b) points[fill[mpData[p].nIN[b]]++] = p;
  std::vector<int> seen(nodes, -1), rowStart(nodes + 1, 0), rows;  // each column's distinct
  for (int n = 0; n < nodes; ++n) {                                  // row nodes, ascending
    for (int e = start[n]; e < start[n + 1]; ++e) {
      const MaterialPoint& mp = mpData[points[e]];
      for (int a = 0; a < mp.nn; ++a)
        if (seen[mp.nIN[a]] != n) seen[mp.nIN[a]] = n, rows.push_back(mp.nIN[a]);
    }
    std::sort(rows.begin() + rowStart[n], rows.end());
    rowStart[n + 1] = int(rows.size());
  }
  SpMat K(nDoF, nDoF);                                                // compressed, written
  K.resizeNonZeros(nD * nD * rowStart[nodes]);                       // directly: column dof(n, k)
  int *outer = K.outerIndexPtr(), *inner = K.innerIndexPtr(), k = 0;  // has the rows dof(r, i) of
  for (int n = 0; n < nodes; ++n)                                    // node n's row nodes r
    for (int c = 0; c < nD; ++c) {
      outer[dof(n, c)] = k;
      for (int e = rowStart[n]; e < rowStart[n + 1]; ++e)
        for (int i = 0; i < nD; ++i) inner[k++] = dof(rows[e], i);
    }
  outer[nDoF] = k;
  K.coeffs().setZero();
  return K;
}

// Kt's pattern already holds the entries of ke: walk each column once from the
// point's first dof instead of searching for every entry (any pattern, any dofs)
void addToPattern(const SpMat& Kt, double* val, const int* d, int n,
                  const Eigen::Ref<const Eigen::MatrixXd>& ke, int c0, int c1) {
  const int* inner = Kt.innerIndexPtr();
  for (int q = 0; q < n; ++q) {
    if (d[q] < c0 || d[q] >= c1) continue;
    int pos = int(std::lower_bound(inner + Kt.outerIndexPtr()[d[q]],
                                   inner + Kt.outerIndexPtr()[d[q] + 1], d[0]) - inner);
    for (int p = 0; p < n; ++p) {
      while (inner[pos] < d[p]) ++pos;
      val[pos] += ke(p, q);
    }
  }
}

// every node pair of the pattern is a full 2 x 2 block, and the two columns of a
// node have the same rows (true for stiffnessPattern's; a grown pattern is checked)
bool nodeBlocked(const SpMat& Kt) {
  const int* outer = Kt.outerIndexPtr();
  const int* inner = Kt.innerIndexPtr();
  if (Kt.rows() % nD != 0 || Kt.cols() % nD != 0 || !Kt.isCompressed()) return false;
  for (int c = 0; c < Kt.cols(); c += nD) {
    const int len = outer[c + 1] - outer[c];
    if (outer[c + 2] - outer[c + 1] != len || len % nD != 0) return false;
    for (int e = outer[c]; e < outer[c + 1]; e += nD)
      if (inner[e] % nD != 0 || inner[e + 1] != inner[e] + 1 || inner[e + len] != inner[e] ||
          inner[e + len + 1] != inner[e] + 1)
        return false;
  }
  return true;
}

// a node-blocked pattern: one search per node column b, then a walk by node
// pairs; the 2 x 2 block of nodes (a, b) sits at pos, pos + 1 (column x of b)
// and pos + len, pos + len + 1 (column y of b)
void nodeBlockPositions(const SpMat& Kt, const int* nIN, int nn, int* at) {
  static_assert(nD == 2, "the 2 x 2 node blocks");
  const int* outer = Kt.outerIndexPtr();
  const int* inner = Kt.innerIndexPtr();
  for (int b = 0; b < nn; ++b) {
    const int cx = dof(nIN[b], 0);
    int pos = int(std::lower_bound(inner + outer[cx], inner + outer[cx + 1], dof(nIN[0], 0)) - inner);
    for (int a = 0; a < nn; ++a) {
      while (inner[pos] < dof(nIN[a], 0)) pos += nD;
      at[nn * b + a] = pos;
    }
  }
}

void addNodeBlocks(const SpMat& Kt, double* val, const int* nIN, int nn, const int* at,
                   const Eigen::Ref<const Eigen::MatrixXd>& ke, int n0, int n1) {
  const int* outer = Kt.outerIndexPtr();
  for (int b = 0; b < nn; ++b) {
    if (nIN[b] < n0 || nIN[b] >= n1) continue;
    const int cx = dof(nIN[b], 0), len = outer[cx + 1] - outer[cx];
    for (int a = 0; a < nn; ++a) {
      const int pos = at[nn * b + a];
      val[pos] += ke(2 * a, 2 * b);
      val[pos + 1] += ke(2 * a + 1, 2 * b);
      val[pos + len] += ke(2 * a, 2 * b + 1);
      val[pos + len + 1] += ke(2 * a + 1, 2 * b + 1);
    }
  }
}

}  // namespace ample
