//--------------------------------------------------------------------------
// MPMbasis — two-dimensional basis functions and gradients of one point
//--------------------------------------------------------------------------
// Seed 002 eq 22. See MPMbasis.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "MPMbasis.h"
#include "SvpCPDI.h"
#include "SvpGIMP.h"
#include "SvpMPM.h"

namespace ample {

double gridBasis(const Mesh& mesh, int node, const Vector2d& x) {
  return SvpMPM(x(0) - mesh.coord(node, 0), mesh.h(0)).S * SvpMPM(x(1) - mesh.coord(node, 1), mesh.h(1)).S;
}

static void cpdiBasis(const Mesh& mesh, MaterialPoint& mp) {
  const Corners x = domainCorners(mp);
  for (int v = 0; v < mp.nn; ++v) {
    Eigen::Vector4d Sc;  // grid basis of node v at the four corners
    for (int c = 0; c < 4; ++c) Sc(c) = gridBasis(mesh, mp.nIN[v], x.col(c));
    const Basis2D b = (mp.mpType == MpType::CPDI1) ? SvpCPDI1(Sc, mp.st) : SvpCPDI2(Sc, x);
    mp.Svp[v] = b.S;
    mp.dSvp.col(v) = b.dS;
  }
}

void MPMbasis(const Mesh& mesh, MaterialPoint& mp) {
  if (isCPDI(mp)) return cpdiBasis(mesh, mp);
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
}

}  // namespace ample
