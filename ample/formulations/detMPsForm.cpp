//--------------------------------------------------------------------------
// detMPsForm — the point loop of the other formulations: PC and SS
//--------------------------------------------------------------------------
// [Lagrangian] eqs 18-23 (PC); [Boundaries] eqs 2-3, 6, 8-10 (SS). See
// detMPsForm.h for the equations, inputs and outputs.
//--------------------------------------------------------------------------
#include "detMPsForm.h"
#include "ample/errors.h"
#include "ample/stiffness/formPCstiff.h"
#include "ample/stiffness/formULstiff.h"
#include "ample/stiffness/tensorOps.h"
#include "ample/pointModel.h"

namespace ample {

namespace {

using PointDofs = Eigen::Matrix<int, Eigen::Dynamic, 1, 0, nD * MAXN, 1>;          // 2 nn, no heap
using PointMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, nD * MAXN, nD * MAXN>;
using StrainDisplacement = Eigen::Matrix<double, 4, Eigen::Dynamic, 0, 4, nD * MAXN>;  // G: 4 x 2 nn

struct StartTerms {            // a point's terms of eqs 14 and 16 on the step's start configuration
  Eigen::Matrix4d A;           // tangent, (i,j) -> 2i+j
  Eigen::Vector4d S;           // the stress paired with dS/dX~, S_ij at 2i+j
  double V;                    // the volume
};


// PC ([Lagrangian] eqs 18-23): the state of [AMPLE] eqs 5-11, then P~ and its tangent
StartTerms previouslyConverged(const Matrix3d& dF, MaterialPoint& mp) {
  mp.F = dF * mp.Fn;                                                                     // eq 7
  const Matrix3d bEn = symExp(2.0 * strainToTensor(mp.epsEn));                          // eq 9
  const Matrix3d bEtr = dF * bEn * dF.transpose();                                      // eq 8
  const ConstOut cm = pointModel(tensorToStrain(0.5 * symLog(bEtr)), mp);            // eqs 10, 5, 11
  mp.epsE = cm.epsE;
  mp.sig = cm.Ksig / mp.F.determinant();                                                 // eq 6
  const double Jn = mp.Fn.determinant();
  const Matrix3d tau = stressToTensor(cm.Ksig);
  const Matrix3d P = tau * dF.inverse().transpose() / Jn;                               // P~, eq 18
  return {formPCstiff2D(dF, Jn, cm.D, tau, bEn, bEtr), P.topLeftCorner<2, 2>().reshaped<Eigen::RowMajor>(),
          mp.vp};                                               // V_p^n
}

// SS ([Boundaries] eqs 2-3, 10): eps = eps_n + sym(grad du), sigma from the model, A = D
StartTerms smallStrain(const Eigen::Matrix2d& H, MaterialPoint& mp) {
  Matrix3d e = Matrix3d::Zero();
  e.topLeftCorner<2, 2>() = 0.5 * (H + H.transpose());                                  // sym(grad du)
  const ConstOut cm = pointModel(mp.epsEn + tensorToStrain(e), mp);                   // eqs 2, 3
  mp.F = Matrix3d::Identity();
  mp.epsE = cm.epsE;
  mp.sig = cm.Ksig;                                                                      // Cauchy stress
  return {elasticBlock2D(cm.D), stressToTensor(mp.sig).topLeftCorner<2, 2>().reshaped<Eigen::RowMajor>(),
          mp.vp};                                               // V_p = V_p0
}

}  // namespace

void detMPsForm(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData, Formulation form,
                DetMPsOut& out) {
  if (form == Formulation::UL) throw InputError("detMPsForm: PC or SS; UL is detMPs' (pointLoopOf)");
  out.fint.setZero(uvw.size());
  std::vector<Eigen::Triplet<double>> Kt;                       // k_p's entries (row, column, value)
  for (size_t p = 0; p < mpData.size(); ++p) {                  // the point loop
    MaterialPoint& mp = mpData[p];
    const int ne = nD * mp.nn;
    PointDofs ed(ne);                                           // its dofs: node v's are 2 v, 2 v + 1
    for (int a = 0; a < ne; ++a) ed(a) = nD * mp.nIN[a / nD] + a % nD;
    Eigen::Matrix2d H = Eigen::Matrix2d::Zero();               // grad du = sum_v du_v (x) dS_v/dX~
    for (int v = 0; v < mp.nn; ++v) H += uvw.segment<nD>(nD * mp.nIN[v]) * mp.dSvp.col(v).transpose();
    Matrix3d dF = Matrix3d::Identity();
    dF.topLeftCorner<2, 2>() += H;                                                          // eq 17
    const StartTerms t = form == Formulation::PC ? previouslyConverged(dF, mp) : smallStrain(H, mp);
    StrainDisplacement G = StrainDisplacement::Zero(4, ne);     // of dS/dX~: G(2k+l, 2b+k) = dS_b/dX_l
    for (int b = 0; b < mp.nn; ++b) G.block<2, 1>(0, nD * b) = G.block<2, 1>(2, nD * b + 1) = mp.dSvp.col(b);
    const PointMatrix kp = t.V * G.transpose() * t.A * G;       // k_p on the step's start (eq 14)
    out.fint(ed) += t.V * G.transpose() * t.S;                  // f_p on the step's start (eq 16), eq 31
    for (int c = 0; c < ne; ++c)                                // Kt (eq 30)
      for (int r = 0; r < ne; ++r) Kt.emplace_back(ed(r), ed(c), kp(r, c));
  }
  out.Kt.resize(uvw.size(), uvw.size());
  out.Kt.setFromTriplets(Kt.begin(), Kt.end());
}

PointLoop pointLoopOf(Formulation form) {
  return form == Formulation::UL ? PointLoop(detMPs) : PointLoop(detMPsForm);
}

DetMPsOut detMPsOf(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData, Formulation form) {
  DetMPsOut out;
  pointLoopOf(form)(uvw, mpData, form, out);
  return out;
}

}  // namespace ample
