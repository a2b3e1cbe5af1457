//--------------------------------------------------------------------------
// elemMPinfo — cells, nodes, basis functions and gradients of every point
//--------------------------------------------------------------------------
// [AMPLE] sec 4. See elemMPinfo.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "elemMPinfo.h"
#include "ample/basis/MPMbasis.h"
#include "ample/basis/elemForMP.h"
#include "ample/basis/nodesForMP.h"

namespace ample {

void elemMPinfo(Mesh& mesh, std::vector<MaterialPoint>& mpData) {
  for (size_t p = 0; p < mpData.size(); ++p) pointInfo(mesh, mpData[p], p);  // the points
  markActiveCells(mesh, mpData);
}

// point p's cells (elemForMP), its nodes (nodesForMP), S_vp and dS_vp (MPMbasis)
void pointInfo(const Mesh& mesh, MaterialPoint& mp, size_t p) {
  try {
    mp.ne = elemForMP(mesh, mp.mpC, mp.lp, mp.eIN);
  } catch (const RunError& e) {
    throw atPoint(p, e);
  }
  pointNodes(mesh, mp);
  MPMbasis(mesh, mp);
}

// the nodes of the point's cells (nodesForMP), and its basis arrays cleared for the basis to fill
void pointNodes(const Mesh& mesh, MaterialPoint& mp) {
  mp.nIN.fill(0);
  mp.nn = nodesForMP(mesh, mp.eIN, mp.ne, mp.nIN.data());
  mp.Svp.fill(0.0);
  mp.dSvp.setZero();
}

// the active cells: those holding points (detFDoFs)
void markActiveCells(Mesh& mesh, const std::vector<MaterialPoint>& mpData) {
  mesh.eInA.assign(mesh.nels(), 0);
  for (const MaterialPoint& mp : mpData)
    for (int e = 0; e < mp.ne; ++e) mesh.eInA[mp.eIN[e]] = 1;
}

RunError atPoint(size_t p, const RunError& e) {
  return RunError("point " + std::to_string(p) + ": " + e.what(), e.kind);
}

}  // namespace ample
