//--------------------------------------------------------------------------
// updateMPs — material point positions, volumes, domains and state at step end
//--------------------------------------------------------------------------
// Seed 002 eqs 15, 33, 34. See updateMPs.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "updateMPs.h"
#include <Eigen/Eigenvalues>

namespace ample {

Matrix3d stretchTensor(const Matrix3d& F) {
  Eigen::SelfAdjointEigenSolver<Matrix3d> es(F.transpose() * F);
  const Vector3d s = es.eigenvalues().cwiseSqrt();
  return es.eigenvectors() * s.asDiagonal() * es.eigenvectors().transpose();
}

void updateMPs(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData) {
  for (MaterialPoint& mp : mpData) {
    Vector2d du = Vector2d::Zero();                      // eq 33
    for (int v = 0; v < mp.nn; ++v)
      for (int i = 0; i < nD; ++i) du(i) += mp.Svp[v] * uvw(dof(mp.nIN[v], i));
    mp.mpC += du;
    mp.u += du;
    mp.Fn = mp.F;
    mp.epsEn = mp.epsE;
    mp.vp = mp.F.determinant() * mp.vp0;                 // eq 15
    if (mp.mpType == MpType::GIMP) {                     // eq 34
      const Matrix3d U = stretchTensor(mp.F);
      mp.lp = mp.lp0.cwiseProduct(Vector2d(U(0, 0), U(1, 1)));
    }
  }
}

}  // namespace ample
