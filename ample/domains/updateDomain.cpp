//--------------------------------------------------------------------------
// updateDomain — material point domain at the end of a load step
//--------------------------------------------------------------------------
// [Lagrangian] eqs 32-39, [CPDI] sec 2 (vii). See updateDomain.h.
//--------------------------------------------------------------------------
#include "updateDomain.h"
#include "ample/cpdi/cornerBasis.h"
#include "ample/cpdi/domainCorners.h"
#include "ample/stiffness/tensorOps.h"
#include "ample/updateMPs.h"
#include <cmath>

namespace ample {

// corners moved with the grid displacement ([Lagrangian] eq 35, CPDI2)
static Corners moveCorners(const Mesh& mesh, const Eigen::VectorXd& uvw, const MaterialPoint& mp,
                           Corners x) {
  const CornerBasis S = cornerBasis(mesh, mp, x);
  for (int c = 0; c < 4; ++c)
    for (int v = 0; v < mp.nn; ++v) x.col(c) += S(v, c) * uvw.segment<nD>(dof(mp.nIN[v], 0));
  return x;
}

// l_i = l_i^ref A_ii (det A / prod_j |A_jj|)^(1/nD), eqs 38-39
static Vector2d volumeCorrectedNormals(const Vector2d& lRef, const Matrix3d& A) {
  const Vector2d d(std::abs(A(0, 0)), std::abs(A(1, 1)));
  const double det = A.topLeftCorner<2, 2>().determinant();
  return lRef.cwiseProduct(d) * std::sqrt(det / (d(0) * d(1)));
}

void updateDomain(const Mesh& mesh, const Eigen::VectorXd& uvw, DomainUpdate method,
                  MaterialPoint& mp) {
  const Matrix3d& F = mp.F;
  const double J = F.topLeftCorner<2, 2>().determinant();
  switch (mp.mpType) {
    case MpType::MPM: return;
    case MpType::CPDI1: mp.cpdi->st = F.topLeftCorner<2, 2>() * mp.cpdi->st0; break;
    case MpType::CPDI2:
      mp.cpdi->xc = moveCorners(mesh, uvw, mp, mp.cpdi->xc);
      mp.vp = quadArea(mp.cpdi->xc);
      break;
    case MpType::GIMP: break;
  }
  if (isCPDI(mp)) {  // lp: half the bounding box of the domain, for output only
    const Corners x = domainCorners(mp);
    mp.lp = 0.5 * (x.rowwise().maxCoeff() - x.rowwise().minCoeff());
    return;
  }
  switch (method) {
    case DomainUpdate::None: mp.lp = mp.lp0; break;
    case DomainUpdate::DetF: mp.lp = mp.lp0 * std::sqrt(J); break;
    case DomainUpdate::Fii: mp.lp = mp.lp0.cwiseProduct(Vector2d(std::abs(F(0, 0)), std::abs(F(1, 1)))); break;
    case DomainUpdate::Uii: updateGIMPDomain(mesh, uvw, mp); break;  // the core's, [AMPLE] eq 34
    case DomainUpdate::Corner: {
      const Corners x = moveCorners(mesh, uvw, mp, domainCorners(mp));
      Corners m;  // edge midpoints: bottom, right, top, left
      for (int c = 0; c < 4; ++c) m.col(c) = 0.5 * (x.col(c) + x.col((c + 1) % 4));
      const Vector2d lm = 0.5 * (m.rowwise().maxCoeff() - m.rowwise().minCoeff());   // eq 36
      mp.lp = lm * std::sqrt(J * mp.lp0.prod() / lm.prod());                          // eq 37
      break;
    }
    case DomainUpdate::FiiVol: mp.lp = volumeCorrectedNormals(mp.lp0, F); break;
    case DomainUpdate::FiiVolInc: mp.lp = volumeCorrectedNormals(mp.lp, F * mp.Fn.inverse()); break;
  }
}

}  // namespace ample
