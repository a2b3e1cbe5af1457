//--------------------------------------------------------------------------
// stiffnessPattern — the sparsity of Kt for one load step
//--------------------------------------------------------------------------
// See stiffnessPattern.h for inputs and outputs.
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

}  // namespace ample
