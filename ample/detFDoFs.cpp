//--------------------------------------------------------------------------
// detFDoFs — free degrees of freedom of the background grid
//--------------------------------------------------------------------------
// See detFDoFs.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "detFDoFs.h"

namespace ample {

std::vector<int> detFDoFs(const Mesh& mesh) {
  std::vector<char> isFree(mesh.nDoF(), 0);
  for (int e = 0; e < mesh.nels(); ++e)
    if (mesh.eInA[e])
      for (int a = 0; a < nen; ++a)
        for (int i = 0; i < nD; ++i) isFree[dof(mesh.etpl(e, a), i)] = 1;
  for (const BC& c : mesh.bc) isFree[c.dof] = 0;
  std::vector<int> fd;
  for (int d = 0; d < mesh.nDoF(); ++d)
    if (isFree[d]) fd.push_back(d);
  return fd;
}

}  // namespace ample
