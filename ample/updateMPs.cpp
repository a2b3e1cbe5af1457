//--------------------------------------------------------------------------
// updateMPs — material point positions, volumes, domains and state at step end
//--------------------------------------------------------------------------
// [AMPLE] eqs 15, 33, 34. See updateMPs.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "updateMPs.h"
#include "constitutive/exercise.h"
#include "ample/stiffness/tensorOps.h"

namespace ample {

void updateMPs(const Mesh& mesh, const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData,
               const UpdateDomain& domains) {
  // BEGIN EXERCISE updateMPs
  for (MaterialPoint& mp : mpData) {
    Vector2d du = Vector2d::Zero();                      // eq 33
    for (int v = 0; v < mp.nn; ++v)
      for (int i = 0; i < nD; ++i) du(i) += mp.Svp[v] * uvw(dof(mp.nIN[v], i));
    mp.vp = mp.F.determinant() * mp.vp0;                 // eq 15
    domains.updateDomain(mesh, uvw, mp);                 // eq 34 (before the point moves)
    mp.mpC += du;
    mp.u += du;
    mp.Fn = mp.F;
    mp.epsEn = mp.epsE;
  }
  // END EXERCISE
}

void updateGIMPDomain(const Mesh& /*mesh*/, const Eigen::VectorXd& /*uvw*/, MaterialPoint& mp) {
  if (mp.mpType != MpType::GIMP) return;                 // standard MPM: no domain
  const Matrix3d U = stretchTensor(mp.F);                // F = R U
  mp.lp = mp.lp0.cwiseProduct(Vector2d(U(0, 0), U(1, 1)));  // eq 34
}

void moveMesh(Mesh& mesh, const Eigen::VectorXd& uvw) {
  for (int n = 0; n < mesh.nodes(); ++n)
    for (int i = 0; i < nD; ++i) mesh.coord(n, i) += uvw(dof(n, i));
}

}  // namespace ample
