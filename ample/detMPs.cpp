//--------------------------------------------------------------------------
// detMPs — internal force and stiffness of all material points (the point loop)
//--------------------------------------------------------------------------
// Seed 002 eqs 5-18, 30-31. See detMPs.h for the steps, inputs and outputs.
//--------------------------------------------------------------------------
#include "detMPs.h"
#include "constitutive/Hooke3d.h"
#include "constitutive/VMconst.h"
#include "formPCstiff.h"
#include "tensorOps.h"

namespace ample {

DetMPsOut detMPs(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData,
                 Formulation form) {
  const int nDoF = int(uvw.size());
  DetMPsOut out{Eigen::VectorXd::Zero(nDoF), SpMat(nDoF, nDoF)};
  size_t nSMe = 0;  // number of stiffness matrix entries
  for (const MaterialPoint& mp : mpData) nSMe += size_t(nD * mp.nn) * size_t(nD * mp.nn);
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(nSMe);

  for (MaterialPoint& mp : mpData) {
    Matrix3d dF = Matrix3d::Identity();                           // eq 17
    for (int v = 0; v < mp.nn; ++v)
      for (int i = 0; i < nD; ++i)
        for (int j = 0; j < nD; ++j) dF(i, j) += uvw(dof(mp.nIN[v], i)) * mp.dSvp(j, v);
    mp.F = dF * mp.Fn;                                            // eq 7
    const Matrix3d bEn = symExp(2.0 * strainToTensor(mp.epsEn));  // eq 9
    const Matrix3d BeT = dF * bEn * dF.transpose();               // eq 8
    const Vector6d epsEtr = tensorToStrain(0.5 * symLog(BeT));    // eq 10

    const ConstOut cm = (mp.cmType == CmType::Elastic) ? Hooke3d(epsEtr, mp.mCst)
                                                       : VMconst(epsEtr, mp.mCst);
    mp.epsE = cm.epsE;
    mp.sig = cm.Ksig / mp.F.determinant();                        // eq 6

    Matrix9d A;                                                   // tangent
    Eigen::Matrix2d Sf;                                           // stress paired with dSx
    Eigen::Matrix<double, nD, MAXN> dSx;                          // basis gradients
    double Vp;                                                    // volume
    if (form == Formulation::UL) {                                // seed 002 eqs 14-18
      A = formULstiff(mp.F, cm.D, mp.sig, BeT);                   // seed 000 eq A.1
      const Eigen::Matrix2d iF = dF.topLeftCorner<2, 2>().inverse();
      dSx.leftCols(mp.nn) = iF.transpose() * mp.dSvp.leftCols(mp.nn);  // eq 18: dS/dx
      Vp = dF.determinant() * mp.vp;                              // eq 15
      Sf = stressToTensor(mp.sig).topLeftCorner<2, 2>();
    } else {                                                      // seed 000 eqs 18-23
      const double Jn = mp.Fn.determinant();
      const Matrix3d tau = stressToTensor(cm.Ksig);
      A = formPCstiff(dF, Jn, cm.D, tau, bEn, BeT);               // seed 000 eq A.3
      dSx.leftCols(mp.nn) = mp.dSvp.leftCols(mp.nn);              // dS/dX~, no mapping
      Vp = mp.vp;                                                 // V_p^n (eq 22)
      Sf = (tau * dF.inverse().transpose() / Jn).topLeftCorner<2, 2>();  // P~ (eq 18)
    }

    for (int a = 0; a < mp.nn; ++a)
      for (int i = 0; i < nD; ++i) {
        double fa = 0.0;                                          // eq 16
        for (int j = 0; j < nD; ++j) fa += dSx(j, a) * Sf(i, j);
        out.fint(dof(mp.nIN[a], i)) += fa * Vp;
        for (int b = 0; b < mp.nn; ++b)
          for (int k = 0; k < nD; ++k) {
            double kab = 0.0;                                     // eq 14
            for (int j = 0; j < nD; ++j)
              for (int l = 0; l < nD; ++l) kab += dSx(j, a) * A(3 * i + j, 3 * k + l) * dSx(l, b);
            trip.emplace_back(dof(mp.nIN[a], i), dof(mp.nIN[b], k), kab * Vp);
          }
      }
  }
  out.Kt.setFromTriplets(trip.begin(), trip.end());
  return out;
}

}  // namespace ample
