//--------------------------------------------------------------------------
// elemMPinfoMesh — elemMPinfo on a general mesh of triangles or quadrilaterals
//--------------------------------------------------------------------------
// docs/meshes.md. See elemMPinfoMesh.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "elemMPinfoMesh.h"
#include "cellBasis.h"
#include "cellSearch.h"
#include "ample/elemMPinfo.h"
#include "ample/errors.h"

namespace ample {

void elemMPinfoMesh(Mesh& mesh, std::vector<MaterialPoint>& mpData, bool keepCells) {
  buildCellSearch(mesh);                        // a setup may have moved the mesh's nodes
  for (size_t p = 0; p < mpData.size(); ++p) meshPointInfo(mesh, mpData[p], p, keepCells);
  markActiveCells(mesh, mpData);
}

// point p's cell, its nodes, S_vp and dS_vp
void meshPointInfo(const Mesh& mesh, MaterialPoint& mp, size_t p, bool keepCells) {
  try {
    if (!(keepCells && mp.ne == 1))             // FE mode: the point's own cell, no search
      mp.ne = meshElemForMP(mesh, mp.mpC, mp.lp, mp.eIN);
  } catch (const RunError& e) {
    throw atPoint(p, e);
  }
  pointNodes(mesh, mp);
  meshMPMbasis(mesh, mp);
  dropNullNodes(mp);
}

// the cell that holds the point (cellSearch); a domain needs the grid
int meshElemForMP(const Mesh& mesh, const Vector2d& mpC, const Vector2d& lp,
                  std::array<int, MAXE>& eIN) {
  if (lp(0) > 0.0 || lp(1) > 0.0)
    throw InputError(std::string("mpType=2 (GIMP) needs the regular grid: its domains are squares "
                                 "of grid cells; the background mesh is a ") + meshName(mesh) +
                     " (use mpType=1 MPM, 3 CPDI1 or 4 CPDI2)");
  eIN[0] = cellOf(mesh, mpC);
  return 1;
}

// standard MPM from the basis of the point's one cell (cellBasis); GIMP needs the grid
void meshMPMbasis(const Mesh& mesh, MaterialPoint& mp) {
  if (mp.mpType == MpType::GIMP)
    throw InputError(std::string("mpType=2 (GIMP) needs the regular grid; the background mesh is a ") +
                     meshName(mesh) + " (use mpType=1 MPM, 3 CPDI1 or 4 CPDI2)");
  const int e = mp.eIN[0];
  const CellBasis b = cellBasis(mesh, e, mp.mpC);
  for (int v = 0; v < mp.nn; ++v) {
    const int a = localNode(mesh, e, mp.nIN[v]);
    mp.Svp[v] = b.N[a];
    mp.dSvp.col(v) = b.dN.col(a);
  }
}

int dropNullNodes(MaterialPoint& mp) {
  int k = 0;
  for (int v = 0; v < mp.nn; ++v) {
    if (mp.Svp[v] == 0.0 && mp.dSvp.col(v).isZero(0.0)) continue;
    mp.nIN[k] = mp.nIN[v];
    mp.Svp[k] = mp.Svp[v];
    mp.dSvp.col(k) = mp.dSvp.col(v);
    ++k;
  }
  for (int v = k; v < mp.nn; ++v) {
    mp.nIN[v] = 0;
    mp.Svp[v] = 0.0;
    mp.dSvp.col(v).setZero();
  }
  return mp.nn = k;
}

}  // namespace ample
