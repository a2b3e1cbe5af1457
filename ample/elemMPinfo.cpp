//--------------------------------------------------------------------------
// elemMPinfo — cells, nodes, basis functions and gradients of every point
//--------------------------------------------------------------------------
// [AMPLE] sec 4. See elemMPinfo.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "elemMPinfo.h"
#include "ample/basis/MPMbasis.h"
#include "ample/meshes/cellSearch.h"
#include "ample/basis/elemForMP.h"
#include "errors.h"
#include "ample/basis/domainCorners.h"
#include "ample/basis/nodesForMP.h"
#include <algorithm>

namespace ample {

// CPDI: the cells that contain the four domain corners ([CPDI] sec 2 (iii));
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

// drop the nodes whose basis value and gradient at the point are both exactly zero:
// they carry no mass, force or stiffness from it, and linked they would put a dof
// with an empty stiffness column into the system. This happens to CPDI points
// whose corner lies on the far edge of its cell (e.g. a corner on the base, y = 0:
// N = 0 there for the nodes of the cell's upper edge, [CPDI] sec 2 (iii));
// GIMP/MPM cells are linked only when overlapped, so they lose no nodes.
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

static RunError atPoint(size_t p, const RunError& e) {  // the error of point p
  return RunError("point " + std::to_string(p) + ": " + e.what(), e.kind);
}

// one point's cells on the regular grid: elemForMP, or the cells of its corners for CPDI
static void gridCells(const Mesh& mesh, MaterialPoint& mp, size_t p, bool keepCells) {
  try {
    if (keepCells && mp.ne == 1) {}               // FE mode: the point's own cell, no search
    else if (isCPDI(mp)) mp.ne = cellsOfCorners(mesh, mp, mp.eIN);
    else mp.ne = elemForMP(mesh, mp.mpC, mp.lp, mp.eIN);
  } catch (const RunError& e) {
    throw atPoint(p, e);
  }
}

// CPDI on a general mesh: the cells of the four corners (cornerCell: on an edge the
// domain's side; outside the mesh the last cell on the way from the point)
static int meshCellsOfCorners(const Mesh& mesh, const MaterialPoint& mp, std::array<int, MAXE>& eIN) {
  cellOf(mesh, mp.mpC);  // throws if the point left the mesh
  const Corners x = domainCorners(mp);
  int ne = 0;
  for (int c = 0; c < 4; ++c) {
    const int e = cornerCell(mesh, x.col(c), mp.mpC);
    if (std::find(eIN.begin(), eIN.begin() + ne, e) == eIN.begin() + ne) eIN[ne++] = e;
  }
  std::sort(eIN.begin(), eIN.begin() + ne);
  return ne;
}

// the same on a general mesh (docs/meshes.md): the cell that holds the point
// (meshElemForMP), or the cells of its corners for CPDI
static void meshCells(const Mesh& mesh, MaterialPoint& mp, size_t p, bool keepCells) {
  try {
    if (keepCells && mp.ne == 1) {}               // FE mode: the point's own cell, no search
    else if (isCPDI(mp)) mp.ne = meshCellsOfCorners(mesh, mp, mp.eIN);
    else mp.ne = meshElemForMP(mesh, mp.mpC, mp.lp, mp.eIN);
  } catch (const RunError& e) {
    throw atPoint(p, e);
  }
}

// point p's cells (the grid's or a general mesh's; p: its index, for messages)
void pointCells(const Mesh& mesh, MaterialPoint& mp, size_t p, bool keepCells) {
  if (mesh.regular()) gridCells(mesh, mp, p, keepCells);
  else meshCells(mesh, mp, p, keepCells);
}

// a point's nodes, S_vp and dS_vp (from its cells)
void pointBasis(const Mesh& mesh, MaterialPoint& mp) {
  mp.nIN.fill(0);
  mp.nn = nodesForMP(mesh, mp.eIN, mp.ne, mp.nIN.data());
  mp.Svp.fill(0.0);
  mp.dSvp.setZero();
  if (mesh.regular()) MPMbasis(mesh, mp);
  else meshMPMbasis(mesh, mp);
  dropNullNodes(mp);
}

// the active cells: those holding points (detFDoFs)
void markActiveCells(Mesh& mesh, const std::vector<MaterialPoint>& mpData) {
  mesh.eInA.assign(mesh.nels(), 0);
  for (const MaterialPoint& mp : mpData)
    for (int e = 0; e < mp.ne; ++e) mesh.eInA[mp.eIN[e]] = 1;
}

void elemMPinfo(Mesh& mesh, std::vector<MaterialPoint>& mpData, bool keepCells) {
  if (!mesh.regular()) buildCellSearch(mesh);   // a setup may have moved the mesh's nodes
  for (size_t p = 0; p < mpData.size(); ++p) {  // the points
    pointCells(mesh, mpData[p], p, keepCells);  // eIN, ne (elemForMP)
    pointBasis(mesh, mpData[p]);                // nIN, nn (nodesForMP); Svp, dSvp (MPMbasis)
  }
  markActiveCells(mesh, mpData);
}

}  // namespace ample
