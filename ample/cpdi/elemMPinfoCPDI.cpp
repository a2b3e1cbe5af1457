//--------------------------------------------------------------------------
// elemMPinfoCPDI — elemMPinfo for a run with CPDI points, on either mesh
//--------------------------------------------------------------------------
// [CPDI] sec 2 (iii)-(iv). See elemMPinfoCPDI.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "elemMPinfoCPDI.h"
#include "SvpCPDI.h"
#include "ample/basis/elemForMP.h"
#include "ample/elemMPinfo.h"
#include "ample/meshes/cellSearch.h"
#include "ample/meshes/elemMPinfoMesh.h"
#include <algorithm>

namespace ample {

static int gridCellsOfCorners(const Mesh& mesh, const MaterialPoint& mp, std::array<int, MAXE>& eIN);
static int meshCellsOfCorners(const Mesh& mesh, const MaterialPoint& mp, std::array<int, MAXE>& eIN);

void elemMPinfoCPDI(Mesh& mesh, std::vector<MaterialPoint>& mpData, bool keepCells) {
  if (!mesh.regular()) buildCellSearch(mesh);   // a setup may have moved the mesh's nodes
  for (size_t p = 0; p < mpData.size(); ++p) {  // the points
    if (isCPDI(mpData[p])) cpdiPointInfo(mesh, mpData[p], p);
    else if (mesh.regular()) pointInfo(mesh, mpData[p], p);
    else meshPointInfo(mesh, mpData[p], p, keepCells);
  }
  markActiveCells(mesh, mpData);
}

// CPDI point p's cells (those of its corners), nodes, S_vp and dS_vp
void cpdiPointInfo(const Mesh& mesh, MaterialPoint& mp, size_t p) {
  try {
    mp.ne = mesh.regular() ? gridCellsOfCorners(mesh, mp, mp.eIN) : meshCellsOfCorners(mesh, mp, mp.eIN);
  } catch (const RunError& e) {
    throw atPoint(p, e);
  }
  pointNodes(mesh, mp);
  const Corners x = domainCorners(mp);
  cpdiBasis(mp, x, cornerBasis(mesh, mp, x));
  dropNullNodes(mp);
}

// CPDI1 / CPDI2 from the basis of each node at the four corners S(v, c)
void cpdiBasis(MaterialPoint& mp, const Corners& x, const CornerBasis& S) {
  for (int v = 0; v < mp.nn; ++v) {
    const Eigen::Vector4d Sc = S.row(v).transpose();  // basis of node v at the four corners
    const Basis2D b = (mp.mpType == MpType::CPDI1) ? SvpCPDI1(Sc, mp.cpdi->st) : SvpCPDI2(Sc, x);
    mp.Svp[v] = b.S;
    mp.dSvp.col(v) = b.dS;
  }
}

// the regular grid: the cells that contain the four corners; a corner on a cell edge is
// taken into the cell on the domain's side of it, a corner past the grid edge into the
// cell at the edge (the point must be inside)
static int gridCellsOfCorners(const Mesh& mesh, const MaterialPoint& mp, std::array<int, MAXE>& eIN) {
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

// a general mesh: the cells of the four corners (cornerCell: on an edge the domain's
// side; outside the mesh the last cell on the way from the point)
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

}  // namespace ample
