//--------------------------------------------------------------------------
// addPoint — one point of the fast point loop: its state, f_p and k_p, unrolled
//--------------------------------------------------------------------------
// See addPoint.h. [AMPLE] eqs 5-18; [Lagrangian] eqs 18-23 (PC); [Boundaries]
// eqs 2-3, 8-10 (SS).
//--------------------------------------------------------------------------
#include "addPoint.h"
#include "ample/stiffness/formPCstiff.h"
#include "ample/stiffness/formULstiff.h"
#include "ample/pointModel.h"

namespace ample {

namespace {

struct PointTerms {                          // what eqs 14 and 16 need of one point
  Eigen::Matrix4d A;                         // in-plane tangent, (i,j) -> 2i+j
  Eigen::Matrix2d Sf;                        // stress paired with dSx
  Eigen::Matrix<double, nD, MAXN> dSx;       // basis gradients
  double Vp;                                 // volume
};

// start + grad du, grad du = sum_v du_v (x) dS_v/dX~ (in-plane block): dF with
// start = I (eq 17); grad du itself with start = 0 (SS: no 1 + small - 1)
Matrix3d plusGradDu(Matrix3d start, const Eigen::VectorXd& uvw, const MaterialPoint& mp) {
  for (int v = 0; v < mp.nn; ++v)                               // du_v (x) dS_v/dX~, node v's dofs
    start.topLeftCorner<2, 2>() += uvw.segment<nD>(nD * mp.nIN[v]) * mp.dSvp.col(v).transpose();
  return start;
}


//--------------------------------------------------------------------------
// finiteStrainPoint — UL ([AMPLE] eqs 5-18) or PC ([Lagrangian] eqs 18-23)
//--------------------------------------------------------------------------
// Logarithmic elastic strain, Kirchhoff stress tau, sigma = tau / det(F).
// bEn = exp(2 eps_e,n) (eq 9) is that of the start of the step: elasticLeftCG
// computes it once per load step. Writes mp.F, mp.epsE, mp.sig (trial values
// until the step converges).
//--------------------------------------------------------------------------
PointTerms finiteStrainPoint(const Matrix3d& dF, const Matrix3d& bEn, Formulation form,
                             MaterialPoint& mp) {                // bEn = exp(2 eps_e,n), eq 9
  mp.F = dF * mp.Fn;                                            // eq 7
  const Matrix3d BeT = dF * bEn * dF.transpose();               // eq 8
  const InPlaneEigen eig = inPlaneEigen(BeT);                   // once for eq 10 and eq A.2
  const Vector6d epsEtr = tensorToStrain(0.5 * inPlaneLog(eig));    // eq 10

  const ConstOut cm = pointModel(epsEtr, mp);                 // eqs 5, 11
  mp.epsE = cm.epsE;
  mp.sig = cm.Ksig / mp.F.determinant();                        // eq 6

  PointTerms t;
  if (form == Formulation::UL) {                                // [AMPLE] eqs 14-18
    t.A = formULstiff2D(mp.F, cm.D, mp.sig, BeT, dLogdB2D(eig)); // [Lagrangian] eq A.1
    const Eigen::Matrix2d iF = dF.topLeftCorner<2, 2>().inverse();
    t.dSx.leftCols(mp.nn) = iF.transpose() * mp.dSvp.leftCols(mp.nn);  // eq 18: dS/dx
    t.Vp = dF.determinant() * mp.vp;                            // eq 15
    t.Sf = stressToTensor(mp.sig).topLeftCorner<2, 2>();
  } else {                                                      // [Lagrangian] eqs 18-23
    const double Jn = mp.Fn.determinant();
    const Matrix3d tau = stressToTensor(cm.Ksig);
    t.A = formPCstiff2D(dF, Jn, cm.D, tau, bEn, BeT);           // [Lagrangian] eq A.3
    t.dSx.leftCols(mp.nn) = mp.dSvp.leftCols(mp.nn);            // dS/dX~, no mapping
    t.Vp = mp.vp;                                               // V_p^n (eq 22)
    t.Sf = (tau * dF.inverse().transpose() / Jn).topLeftCorner<2, 2>();  // P~ (eq 18)
  }
  return t;
}

//--------------------------------------------------------------------------
// smallStrainPoint — infinitesimal strain, linear elasticity ([Boundaries] sec 2)
//--------------------------------------------------------------------------
// eps = eps_n + sym(grad du), grad du = sum_v du_v (x) dS_v/dX~ with the basis
// gradients of the start of the step ([Boundaries] eqs 2, 10); sigma = D eps (eq 3; cmType VM: the
// same radial return on the small strain); k_p = B' D B V_p, f_p = B' sigma V_p
// (eqs 8-9) with B, V_p those of the start of the step. F stays I (no
// configuration change), so V_p = det(F) V_p0 = V_p0 in updateMPs.
// Writes mp.F = I, mp.epsE, mp.sig (Cauchy).
//--------------------------------------------------------------------------
PointTerms smallStrainPoint(const Matrix3d& H, MaterialPoint& mp) {  // H = grad du
  const Vector6d epsTr = mp.epsEn + tensorToStrain(0.5 * (H + H.transpose()));  // eqs 2, 10

  const ConstOut cm = pointModel(epsTr, mp);                  // eq 3
  mp.F = Matrix3d::Identity();
  mp.epsE = cm.epsE;
  mp.sig = cm.Ksig;                                             // Cauchy stress

  PointTerms t;
  t.A = elasticBlock2D(cm.D);                                   // D (eq 8)
  t.dSx.leftCols(mp.nn) = mp.dSvp.leftCols(mp.nn);              // B: dS/dX~ (eq 6)
  t.Vp = mp.vp;                                                 // V_p = V_p0
  t.Sf = stressToTensor(mp.sig).topLeftCorner<2, 2>();          // sigma (eq 9)
  return t;
}

}  // namespace

//--------------------------------------------------------------------------
// addPoint — f_p (eq 16) of one point added into fint, and its k_p (eq 14) in ke
//--------------------------------------------------------------------------
// k_ab,ik = sum_jl dS_a/dx_j A_ijkl dS_b/dx_l V_p (eq 14) with the products
// g_jkl = dS_a/dx_j A_ijkl formed once per node a and direction i, not per b: half
// the multiplications, the same sums in the same order (bit for bit). Summing over
// j first (12 nn^2 flops) changes the round-off, enough to move where marginal runs stop.
// bEn: exp(2 eps_e,n) of this point (UL, PC; unused for SS).
//--------------------------------------------------------------------------
void addPoint(const Eigen::VectorXd& uvw, const Matrix3d& bEn, Formulation form, MaterialPoint& mp,
              Eigen::VectorXd& fint, PointStiffness& ke) {
  const PointTerms t =
      (form == Formulation::SS)
          ? smallStrainPoint(plusGradDu(Matrix3d::Zero(), uvw, mp), mp)                   // grad du
          : finiteStrainPoint(plusGradDu(Matrix3d::Identity(), uvw, mp), bEn, form, mp);  // dF, eq 17

  int d[nD * MAXN];                                             // the point's dofs, ascending
  for (int a = 0; a < mp.nn; ++a)
    for (int i = 0; i < nD; ++i) d[nD * a + i] = dof(mp.nIN[a], i);
  for (int a = 0; a < mp.nn; ++a)
    for (int i = 0; i < nD; ++i) {
      double fa = 0.0;                                          // eq 16
      for (int j = 0; j < nD; ++j) fa += t.dSx(j, a) * t.Sf(i, j);
      fint(d[nD * a + i]) += fa * t.Vp;
      double g[nD][nD][nD];                                     // g_jkl = dS_a/dx_j A_ijkl, once per a, i
      for (int j = 0; j < nD; ++j)
        for (int k = 0; k < nD; ++k)
          for (int l = 0; l < nD; ++l) g[j][k][l] = t.dSx(j, a) * t.A(2 * i + j, 2 * k + l);
      for (int b = 0; b < mp.nn; ++b)                           // eq 14
        for (int k = 0; k < nD; ++k) {
          double kab = 0.0;
          for (int j = 0; j < nD; ++j)
            for (int l = 0; l < nD; ++l) kab += g[j][k][l] * t.dSx(l, b);
          ke(nD * a + i, nD * b + k) = kab * t.Vp;
        }
    }
}

// exp(2 eps_e,n) of the point (eq 9): its elastic left Cauchy-Green tensor at the start of the step
Matrix3d elasticLeftCG(const MaterialPoint& mp) {
  return inPlaneExp(2.0 * strainToTensor(mp.epsEn));
}

}  // namespace ample
