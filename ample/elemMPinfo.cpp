//--------------------------------------------------------------------------
// elemMPinfo — cells, nodes, basis functions and gradients of every point
//--------------------------------------------------------------------------
// Seed 002 sec 4. See elemMPinfo.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "elemMPinfo.h"
#include "MPMbasis.h"
#include "elemForMP.h"
#include "errors.h"
#include "domainCorners.h"
#include "nodesForMP.h"
#include <algorithm>

namespace ample {

// CPDI: the cells that contain the four domain corners (seed 001 sec 2 (iii));
// a corner on a cell edge is taken into the cell on the domain's side of it,
// a corner past the grid edge into the cell at the edge (the point must be inside)
static int cellsOfCorners(const Mesh& mesh, const MaterialPoint& mp, std::array<int, MAXE>& eIN) {
  std::array<int, MAXE> e;
  elemForMP(mesh, mp.mpC, Vector2d::Zero(), e);  // throws if the point left the grid
  const Corners x = domainCorners(mp);
  const Vector2d lo = mesh.origin, hi = lo + Vector2d(mesh.nelsx * mesh.h(0), mesh.nelsy * mesh.h(1));
  int ne = 0;
  for (int c = 0; c < 4; ++c) {
    const Vector2d xs = (x.col(c) + 1e-6 * (mp.mpC - x.col(c))).cwiseMax(lo).cwiseMin(hi);
    elemForMP(mesh, xs, Vector2d::Zero(), e);
    if (std::find(eIN.begin(), eIN.begin() + ne, e[0]) == eIN.begin() + ne) eIN[ne++] = e[0];
  }
  std::sort(eIN.begin(), eIN.begin() + ne);
  return ne;
}

void elemMPinfo(Mesh& mesh, std::vector<MaterialPoint>& mpData) {
  mesh.eInA.assign(mesh.nels(), 0);
  for (size_t p = 0; p < mpData.size(); ++p) {
    MaterialPoint& mp = mpData[p];
    try {
      if (isCPDI(mp)) mp.ne = cellsOfCorners(mesh, mp, mp.eIN);
      else mp.ne = elemForMP(mesh, mp.mpC, mp.lp, mp.eIN);
    } catch (const RunError& e) {
      throw RunError("point " + std::to_string(p) + ": " + e.what());
    }
    mp.nn = nodesForMP(mesh, mp.eIN, mp.ne, mp.nIN);
    MPMbasis(mesh, mp);
    for (int e = 0; e < mp.ne; ++e) mesh.eInA[mp.eIN[e]] = 1;
  }
}

}  // namespace ample
