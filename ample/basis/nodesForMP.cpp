//--------------------------------------------------------------------------
// nodesForMP — unique list of the nodes of the cells linked to a point
//--------------------------------------------------------------------------
// See nodesForMP.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "nodesForMP.h"
#include <algorithm>

namespace ample {

int nodesForMP(const Mesh& mesh, const std::array<int, MAXE>& eIN, int ne, int* nIN) {
  std::array<int, MAXE * nen> all;
  int n = 0;
  for (int e = 0; e < ne; ++e)
    for (int a = 0; a < mesh.cellNodes(); ++a) all[n++] = mesh.etpl(eIN[e], a);
  std::sort(all.begin(), all.begin() + n);
  const int nn = int(std::unique(all.begin(), all.begin() + n) - all.begin());
  std::copy(all.begin(), all.begin() + nn, nIN);  // at most 16 for 3 x 3 cells
  return nn;
}

}  // namespace ample
