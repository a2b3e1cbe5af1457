//--------------------------------------------------------------------------
// MPMbasis — two-dimensional basis functions and gradients of one point
//--------------------------------------------------------------------------
// [AMPLE] eq 22. See MPMbasis.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "MPMbasis.h"
#include "SvpGIMP.h"
#include "SvpMPM.h"
#include "constitutive/exercise.h"

namespace ample {

void MPMbasis(const Mesh& mesh, MaterialPoint& mp) {
  // BEGIN EXERCISE MPMbasis
  for (int v = 0; v < mp.nn; ++v) {
    Basis1D b[nD];
    for (int i = 0; i < nD; ++i) {
      const double d = mp.mpC(i) - mesh.coord(mp.nIN[v], i);
      b[i] = (mp.mpType == MpType::MPM) ? SvpMPM(d, mesh.h(i)) : SvpGIMP(d, mesh.h(i), mp.lp(i));
    }
    mp.Svp[v] = b[0].S * b[1].S;
    mp.dSvp(0, v) = b[0].dS * b[1].S;
    mp.dSvp(1, v) = b[0].S * b[1].dS;
  }
  // END EXERCISE
}

}  // namespace ample
