//--------------------------------------------------------------------------
// detMPs — internal force and stiffness of all material points (the point loop)
//--------------------------------------------------------------------------
// [AMPLE] eqs 5-18, 30-31 (updated Lagrangian). See detMPs.h for the steps,
// inputs and outputs.
//--------------------------------------------------------------------------
#include "detMPs.h"
#include "errors.h"
#include "constitutive/Hooke3d.h"
#include "constitutive/VMconst.h"
#include "constitutive/exercise.h"
#include "ample/stiffness/formULstiff.h"
#include "ample/stiffness/tensorOps.h"

namespace ample {

using PointDofs = Eigen::Matrix<int, Eigen::Dynamic, 1, 0, nD * MAXN, 1>;          // 2 nn, no heap
using PointVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, nD * MAXN, 1>;
using PointMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, nD * MAXN, nD * MAXN>;
using StrainDisplacement = Eigen::Matrix<double, 4, Eigen::Dynamic, 0, 4, nD * MAXN>;  // G: 4 x 2 nn
using Gradients = Eigen::Matrix<double, nD, Eigen::Dynamic, 0, nD, MAXN>;               // dS/dx: 2 x nn

void detMPs(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData, Formulation form,
            DetMPsOut& out) {
  if (form != Formulation::UL)
    throw InputError("detMPs is the updated Lagrangian point loop (formulation UL): PC and SS are "
                     "those of ample/formulations/ (pointLoopOf)");
  out.fint.setZero(uvw.size());
  std::vector<Eigen::Triplet<double>> Kt;                       // k_p's entries (row, column, value)
  for (size_t p = 0; p < mpData.size(); ++p) {                  // the point loop
    MaterialPoint& mp = mpData[p];                              // the point (gdb: p mp)
    PointDofs ed(nD * mp.nn);                                   // its dofs: node v's are 2 v, 2 v + 1
    for (int a = 0; a < ed.size(); ++a) ed(a) = nD * mp.nIN[a / nD] + a % nD;
    Matrix3d dF = Matrix3d::Identity();                         // eq 17: dF = I + sum_v du_v (x) dS_v/dX~
    for (int v = 0; v < mp.nn; ++v) dF.topLeftCorner<2, 2>() += uvw.segment<nD>(nD * mp.nIN[v]) * mp.dSvp.col(v).transpose();
    mp.F = dF * mp.Fn;                                                                     // eq 7
    const Matrix3d bEtr = dF * symExp(2.0 * strainToTensor(mp.epsEn)) * dF.transpose();   // eqs 8-9
    const Vector6d epsEtr = tensorToStrain(0.5 * symLog(bEtr));                           // eq 10
    const ConstOut cm = mp.cmType == CmType::Elastic ? Hooke3d(epsEtr, mp.mCst) : VMconst(epsEtr, mp.mCst);
    mp.epsE = cm.epsE;                                                                     // eqs 5, 11
    mp.sig = cm.Ksig / mp.F.determinant();                                                 // eq 6
    const Eigen::Matrix4d A = formULstiff2D(mp.F, cm.D, mp.sig, bEtr);  // a_ijkl, (i,j) -> 2i+j
    const Gradients dSx = dF.topLeftCorner<2, 2>().inverse().transpose() * mp.dSvp.leftCols(mp.nn);  // eq 18
    const Eigen::Vector4d sig = stressToTensor(mp.sig).topLeftCorner<2, 2>().reshaped();  // sigma_ij, 2i+j
    const double Vp = dF.determinant() * mp.vp;                                            // eq 15
    // BEGIN EXERCISE detMPs
    StrainDisplacement G = StrainDisplacement::Zero(4, ed.size());       // G(2k+l, 2b+k) = dS_b/dx_l
    for (int b = 0; b < mp.nn; ++b) G.block<2, 1>(0, nD * b) = G.block<2, 1>(2, nD * b + 1) = dSx.col(b);
    const PointMatrix kp = G.transpose() * A * G * Vp;                                    // eq 14
    const PointVector fp = G.transpose() * sig * Vp;                                      // eq 16
    out.fint(ed) += fp;                                                                    // eq 31
    for (int c = 0; c < ed.size(); ++c) for (int r = 0; r < ed.size(); ++r) Kt.emplace_back(ed(r), ed(c), kp(r, c));
    // END EXERCISE
  }
  out.Kt.resize(uvw.size(), uvw.size());
  out.Kt.setFromTriplets(Kt.begin(), Kt.end());                 // eq 30: each entry summed in point order
}

DetMPsOut detMPs(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData, Formulation form) {
  DetMPsOut out;
  detMPs(uvw, mpData, form, out);
  return out;
}

}  // namespace ample
