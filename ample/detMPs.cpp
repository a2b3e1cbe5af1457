//--------------------------------------------------------------------------
// detMPs — internal force and stiffness of all material points (the point loop)
//--------------------------------------------------------------------------
// Seed 002 eqs 5-18, 30-31. See detMPs.h for the steps, inputs and outputs.
//--------------------------------------------------------------------------
#include "detMPs.h"
#include "constitutive/Hooke3d.h"
#include "constitutive/VMconst.h"
#include "formPCstiff.h"
#include "stiffnessPattern.h"
#include "tensorOps.h"

namespace ample {

DetMPsOut detMPs(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData,
                 Formulation form, SpMat pattern) {
  const int nDoF = int(uvw.size());
  if (pattern.rows() != nDoF || pattern.nonZeros() == 0) pattern = stiffnessPattern(nDoF, mpData);
  DetMPsOut out{Eigen::VectorXd::Zero(nDoF), std::move(pattern)};
  out.Kt.coeffs().setZero();                                    // the pattern's values only

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

    Eigen::Matrix4d A;                                            // in-plane tangent, (i,j) -> 2i+j
    Eigen::Matrix2d Sf;                                           // stress paired with dSx
    Eigen::Matrix<double, nD, MAXN> dSx;                          // basis gradients
    double Vp;                                                    // volume
    if (form == Formulation::UL) {                                // seed 002 eqs 14-18
      A = formULstiff2D(mp.F, cm.D, mp.sig, BeT);                 // seed 000 eq A.1
      const Eigen::Matrix2d iF = dF.topLeftCorner<2, 2>().inverse();
      dSx.leftCols(mp.nn) = iF.transpose() * mp.dSvp.leftCols(mp.nn);  // eq 18: dS/dx
      Vp = dF.determinant() * mp.vp;                              // eq 15
      Sf = stressToTensor(mp.sig).topLeftCorner<2, 2>();
    } else {                                                      // seed 000 eqs 18-23
      const double Jn = mp.Fn.determinant();
      const Matrix3d tau = stressToTensor(cm.Ksig);
      A = formPCstiff2D(dF, Jn, cm.D, tau, bEn, BeT);             // seed 000 eq A.3
      dSx.leftCols(mp.nn) = mp.dSvp.leftCols(mp.nn);              // dS/dX~, no mapping
      Vp = mp.vp;                                                 // V_p^n (eq 22)
      Sf = (tau * dF.inverse().transpose() / Jn).topLeftCorner<2, 2>();  // P~ (eq 18)
    }

    int d[nD * MAXN];                                             // the point's dofs, ascending
    for (int a = 0; a < mp.nn; ++a)
      for (int i = 0; i < nD; ++i) d[nD * a + i] = dof(mp.nIN[a], i);
    const int ne = nD * mp.nn;
    Eigen::Matrix<double, nD * MAXN, nD * MAXN> ke;               // eq 14
    for (int a = 0; a < mp.nn; ++a)
      for (int i = 0; i < nD; ++i) {
        double fa = 0.0;                                          // eq 16
        for (int j = 0; j < nD; ++j) fa += dSx(j, a) * Sf(i, j);
        out.fint(d[nD * a + i]) += fa * Vp;
        for (int b = 0; b < mp.nn; ++b)
          for (int k = 0; k < nD; ++k) {
            double kab = 0.0;
            for (int j = 0; j < nD; ++j)
              for (int l = 0; l < nD; ++l) kab += dSx(j, a) * A(2 * i + j, 2 * k + l) * dSx(l, b);
            ke(nD * a + i, nD * b + k) = kab * Vp;
          }
      }
    addToPattern(out.Kt, d, ne, ke.topLeftCorner(ne, ne));      // eq 30
  }
  return out;
}

}  // namespace ample
