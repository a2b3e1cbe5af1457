//--------------------------------------------------------------------------
// elemMPinfoFast — elemMPinfo for large runs: the same result, on threads
//--------------------------------------------------------------------------
// See elemMPinfoFast.h.
//--------------------------------------------------------------------------
#include "elemMPinfoFast.h"
#include "ample/cpdi/elemMPinfoCPDI.h"
#include "ample/meshes/cellSearch.h"
#include "ample/meshes/elemMPinfoMesh.h"
#include "ample/solver/pointShares.h"
#include <algorithm>

namespace ample {

// one point as the serial loop of its run takes it
static void onePoint(const Mesh& mesh, MaterialPoint& mp, size_t p, bool keepCells) {
  if (isCPDI(mp)) cpdiPointInfo(mesh, mp, p);
  else if (mesh.regular()) pointInfo(mesh, mp, p);
  else meshPointInfo(mesh, mp, p, keepCells);
}

void elemMPinfoFast(Mesh& mesh, std::vector<MaterialPoint>& mpData, bool keepCells) {
  const int np = int(mpData.size()), nt = pointThreads(np);
  if (np < fastFrom()) {                        // small: the serial loop the program chooses
    if (std::any_of(mpData.begin(), mpData.end(), [](const MaterialPoint& mp) { return isCPDI(mp); }))
      return elemMPinfoCPDI(mesh, mpData, keepCells);
    if (!mesh.regular()) return elemMPinfoMesh(mesh, mpData, keepCells);
    return elemMPinfo(mesh, mpData);
  }
  if (!mesh.regular()) buildCellSearch(mesh);
  forPointShares(np, nt, [&](int, int begin, int end) {
    for (int p = begin; p < end; ++p) onePoint(mesh, mpData[p], p, keepCells);
  });
  markActiveCells(mesh, mpData);
}

}  // namespace ample
