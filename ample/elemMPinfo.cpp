//--------------------------------------------------------------------------
// elemMPinfo — cells, nodes, basis functions and gradients of every point
//--------------------------------------------------------------------------
// Seed 002 sec 4. See elemMPinfo.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "elemMPinfo.h"
#include "MPMbasis.h"
#include "elemForMP.h"
#include "errors.h"
#include "nodesForMP.h"

namespace ample {

void elemMPinfo(Mesh& mesh, std::vector<MaterialPoint>& mpData) {
  mesh.eInA.assign(mesh.nels(), 0);
  for (size_t p = 0; p < mpData.size(); ++p) {
    MaterialPoint& mp = mpData[p];
    try {
      mp.ne = elemForMP(mesh, mp.mpC, mp.lp, mp.eIN);
    } catch (const RunError& e) {
      throw RunError("point " + std::to_string(p) + ": " + e.what());
    }
    mp.nn = nodesForMP(mesh, mp.eIN, mp.ne, mp.nIN);
    MPMbasis(mesh, mp);
    for (int e = 0; e < mp.ne; ++e) mesh.eInA[mp.eIN[e]] = 1;
  }
}

}  // namespace ample
