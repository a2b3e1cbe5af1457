//--------------------------------------------------------------------------
// splitPoints — split GIMP points whose domains have outgrown their cells
//--------------------------------------------------------------------------
// See splitPoints.h for the rule, inputs and outputs.
//--------------------------------------------------------------------------
#include "splitPoints.h"
#include <cstdio>

namespace ample {

// cut point p in direction i: p becomes the lower half, the upper half is appended
static void cut(std::vector<MaterialPoint>& mpData, size_t p, int i) {
  MaterialPoint half = mpData[p];                  // the whole struct (state and all)
  half.lp(i) *= 0.5;                               // lp(i)/2
  half.lp0(i) *= 0.5;                              // lp0(i)/2: the Uii update keeps lp/lp0
  half.vp *= 0.5;
  half.vp0 *= 0.5;
  half.mpM *= 0.5;
  half.fp *= 0.5;
  MaterialPoint upper = half;
  half.mpC(i) -= half.lp(i);                       // mpC - lp(i)/2 e_i
  upper.mpC(i) += half.lp(i);                      // mpC + lp(i)/2 e_i
  half.X0(i) -= half.lp0(i);                       // X0 -+ lp0(i)/2 e_i
  upper.X0(i) += half.lp0(i);
  half.u = half.mpC - half.X0;                     // total displacement of each centre
  upper.u = upper.mpC - upper.X0;
  mpData[p] = half;
  mpData.push_back(upper);
}

int splitPoints(const Mesh& mesh, double split, std::vector<MaterialPoint>& mpData, bool quiet) {
  if (!(split > 0) || !mesh.regular()) return 0;   // off: nothing read, nothing changed
  int splits = 0;
  for (size_t p = 0; p < mpData.size(); ++p)       // appended halves are checked too
    for (int i = 0; i < nD; ++i)
      while (mpData[p].mpType == MpType::GIMP && mpData[p].lp(i) > split * mesh.h(i)) {
        cut(mpData, p, i);
        ++splits;
      }
  if (splits > 0 && !quiet)
    std::printf("  split %d GIMP point domains longer than %g h: %zu points\n", splits, split, mpData.size());
  return splits;
}

}  // namespace ample
