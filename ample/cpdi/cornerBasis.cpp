//--------------------------------------------------------------------------
// cornerBasis — the basis of each of a point's nodes at each domain corner
//--------------------------------------------------------------------------
// [CPDI] sec 2 (iv). See cornerBasis.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "cornerBasis.h"
#include "ample/basis/SvpMPM.h"
#include "ample/meshes/cellBasis.h"
#include "ample/meshes/cellSearch.h"

namespace ample {

// the bi-linear basis of a grid node, the product of SvpMPM in x and y
double gridBasis(const Mesh& mesh, int node, const Vector2d& x) {
  return SvpMPM(x(0) - mesh.coord(node, 0), mesh.h(0)).S * SvpMPM(x(1) - mesh.coord(node, 1), mesh.h(1)).S;
}

// the regular grid: the grid basis of each of the point's nodes at each corner
static CornerBasis gridCornerBasis(const Mesh& mesh, const MaterialPoint& mp, const Corners& x) {
  CornerBasis S = CornerBasis::Zero();
  for (int v = 0; v < mp.nn; ++v)
    for (int c = 0; c < 4; ++c) S(v, c) = gridBasis(mesh, mp.nIN[v], x.col(c));
  return S;
}

// a general mesh: each corner's cell searched once (outside the mesh: cornerCell's cell,
// its basis continued to the corner), the value of each of the point's nodes there
static CornerBasis meshCornerBasis(const Mesh& mesh, const MaterialPoint& mp, const Corners& x) {
  CornerBasis S = CornerBasis::Zero();
  for (int c = 0; c < 4; ++c) {
    int e = findCell(mesh, x.col(c));
    if (e < 0) e = cornerCell(mesh, x.col(c), mp.mpC);
    const CellBasis b = cellBasis(mesh, e, x.col(c));
    for (int v = 0; v < mp.nn; ++v) {
      const int a = localNode(mesh, e, mp.nIN[v]);
      S(v, c) = a < 0 ? 0.0 : b.N[a];
    }
  }
  return S;
}

CornerBasis cornerBasis(const Mesh& mesh, const MaterialPoint& mp, const Corners& x) {
  return mesh.regular() ? gridCornerBasis(mesh, mp, x) : meshCornerBasis(mesh, mp, x);
}

}  // namespace ample
