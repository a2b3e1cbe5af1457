//--------------------------------------------------------------------------
// elemMPinfoFast — elemMPinfo for large runs: the same result, on threads
//--------------------------------------------------------------------------
// See elemMPinfoFast.h.
//--------------------------------------------------------------------------
#include "elemMPinfoFast.h"
#include "ample/meshes/cellSearch.h"
#include "ample/solver/pointShares.h"

namespace ample {

void elemMPinfoFast(Mesh& mesh, std::vector<MaterialPoint>& mpData, bool keepCells) {
  const int np = int(mpData.size()), nt = pointThreads(np);
  if (np < fastFrom()) return elemMPinfo(mesh, mpData, keepCells);  // small: the core's
  if (!mesh.regular()) buildCellSearch(mesh);
  std::vector<int> nn(np);
  forPointShares(np, nt, [&](int, int begin, int end) {         // 1
    for (int p = begin; p < end; ++p) nn[p] = pointCells(mesh, mpData[p], p, keepCells);
  });
  roomForBasis(mpData, nn);                                     // 2
  forPointShares(np, nt, [&](int, int begin, int end) {         // 3
    for (int p = begin; p < end; ++p) pointBasis(mesh, mpData[p]);
  });
  markActiveCells(mesh, mpData);
}

}  // namespace ample
