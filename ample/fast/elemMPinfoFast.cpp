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
  forPointShares(np, nt, [&](int, int begin, int end) {
    for (int p = begin; p < end; ++p) {
      pointCells(mesh, mpData[p], p, keepCells);
      pointBasis(mesh, mpData[p]);
    }
  });
  markActiveCells(mesh, mpData);
}

}  // namespace ample
