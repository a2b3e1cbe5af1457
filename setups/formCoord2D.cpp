//--------------------------------------------------------------------------
// formCoord2D — regular background grid of bi-linear quadrilaterals
//--------------------------------------------------------------------------
// See formCoord2D.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "formCoord2D.h"

namespace ample {

Mesh formCoord2D(int nelsx, int nelsy, double lx, double ly) {
  Mesh mesh;
  mesh.nelsx = nelsx;
  mesh.nelsy = nelsy;
  mesh.h = Vector2d(lx / nelsx, ly / nelsy);
  mesh.coord.resize((nelsx + 1) * (nelsy + 1), nD);
  for (int j = 0; j <= nelsy; ++j)
    for (int i = 0; i <= nelsx; ++i) {
      const int node = j * (nelsx + 1) + i;
      mesh.coord(node, 0) = lx * i / nelsx;
      mesh.coord(node, 1) = ly * j / nelsy;
    }
  mesh.etpl.resize(nelsx * nelsy, nen);
  for (int j = 0; j < nelsy; ++j)
    for (int i = 0; i < nelsx; ++i) {
      const int bl = j * (nelsx + 1) + i;  // lower-left node
      mesh.etpl.row(j * nelsx + i) << bl, bl + 1, bl + nelsx + 2, bl + nelsx + 1;
    }
  mesh.eInA.assign(nelsx * nelsy, 0);
  return mesh;
}

}  // namespace ample
