//--------------------------------------------------------------------------
// detFDoFs — free degrees of freedom of the background grid
//--------------------------------------------------------------------------
// See detFDoFs.h for the rules, inputs and outputs.
//--------------------------------------------------------------------------
#include "detFDoFs.h"
#include "constitutive/exercise.h"
#include <algorithm>

namespace ample {

static std::vector<int> listFree(std::vector<char>& isFree, const Mesh& mesh) {
  for (const BC& c : mesh.bc) isFree[c.dof] = 0;
  std::vector<int> fd;
  for (int d = 0; d < mesh.nDoF(); ++d)
    if (isFree[d]) fd.push_back(d);
  return fd;
}

std::vector<int> activeCellDoFs(const Mesh& mesh) {
  std::vector<char> isFree(mesh.nDoF(), 0);
  for (int e = 0; e < mesh.nels(); ++e)
    if (mesh.eInA[e])
      for (int a = 0; a < mesh.cellNodes(); ++a)
        for (int i = 0; i < nD; ++i) isFree[dof(mesh.etpl(e, a), i)] = 1;
  return listFree(isFree, mesh);
}

std::vector<int> detFDoFs(const Mesh& mesh, const std::vector<MaterialPoint>& mpData) {
  std::vector<int> links(mesh.nodes(), 0);  // points linked to each node
  std::vector<char> isFree(mesh.nDoF(), 0); // 1: the dof is solved for
  // BEGIN EXERCISE detFDoFs
  for (const MaterialPoint& mp : mpData)
    for (int v = 0; v < mp.nn; ++v) links[mp.nIN[v]]++;
  for (int n = 0; n < mesh.nodes(); ++n)
    if (links[n] > 0)
      for (int i = 0; i < nD; ++i) isFree[dof(n, i)] = 1;
  for (const BC& c : mesh.bc) isFree[c.dof] = 0;
  // END EXERCISE
  std::vector<int> fd;
  for (int d = 0; d < mesh.nDoF(); ++d)
    if (isFree[d]) fd.push_back(d);
  return fd;
}

}  // namespace ample
