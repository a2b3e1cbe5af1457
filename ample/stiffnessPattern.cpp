//--------------------------------------------------------------------------
// stiffnessPattern — the sparsity of Kt for one load step
//--------------------------------------------------------------------------
// Seed 002 eq 30. See stiffnessPattern.h for what it saves, inputs and outputs.
//--------------------------------------------------------------------------
#include "stiffnessPattern.h"
#include <algorithm>

namespace ample {

SpMat stiffnessPattern(int nDoF, const std::vector<MaterialPoint>& mpData) {
  const int nodes = nDoF / nD;
  std::vector<int> start(nodes + 1, 0);  // rows of each node column, with repeats, bucketed
  for (const MaterialPoint& mp : mpData)
    for (int b = 0; b < mp.nn; ++b) start[mp.nIN[b] + 1] += mp.nn;
  for (int n = 0; n < nodes; ++n) start[n + 1] += start[n];
  std::vector<int> rows(start[nodes]), fill(start.begin(), start.end() - 1);
  for (const MaterialPoint& mp : mpData)
    for (int b = 0; b < mp.nn; ++b)
      for (int a = 0; a < mp.nn; ++a) rows[fill[mp.nIN[b]]++] = mp.nIN[a];
  Eigen::VectorXi perColumn = Eigen::VectorXi::Zero(nDoF);
  for (int n = 0; n < nodes; ++n) {      // each column's distinct row nodes, ascending
    auto first = rows.begin() + start[n], last = rows.begin() + start[n + 1];
    std::sort(first, last);
    fill[n] = int(std::unique(first, last) - rows.begin());   // end of the distinct rows
    for (int k = 0; k < nD; ++k) perColumn(dof(n, k)) = nD * int(fill[n] - start[n]);
  }
  SpMat K(nDoF, nDoF);
  K.reserve(perColumn);
  for (int n = 0; n < nodes; ++n)
    for (int k = 0; k < nD; ++k)
      for (int e = start[n]; e < fill[n]; ++e)
        for (int i = 0; i < nD; ++i) K.insert(dof(rows[e], i), dof(n, k)) = 0.0;
  K.makeCompressed();
  return K;
}

// Kt's pattern already holds the entries of ke: walk each column once from the
// point's first dof instead of searching for every entry
void addToPattern(SpMat& Kt, const int* d, int n, const Eigen::Ref<const Eigen::MatrixXd>& ke) {
  const int* inner = Kt.innerIndexPtr();
  double* val = Kt.valuePtr();
  for (int q = 0; q < n; ++q) {
    int pos = int(std::lower_bound(inner + Kt.outerIndexPtr()[d[q]],
                                   inner + Kt.outerIndexPtr()[d[q] + 1], d[0]) - inner);
    for (int p = 0; p < n; ++p) {
      while (inner[pos] < d[p]) ++pos;
      val[pos] += ke(p, q);
    }
  }
}

}  // namespace ample
