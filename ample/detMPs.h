//--------------------------------------------------------------------------
// detMPs — internal force and stiffness of all material points (the point loop)
//--------------------------------------------------------------------------
// [AMPLE] sec 2 (updated Lagrangian): for each point
//   dF = I + sum_v du_v (x) dS_v/dX~            (eq 17)
//   F = dF Fn;  b_e,tr = dF exp(2 eps_e,n) dF'  (eqs 7-9)
//   eps_e,tr = ln(b_e,tr)/2                      (eq 10)
//   tau, D, eps_e from Hooke3d / VMconst         (eqs 5, 11)
//   sigma = tau / det(F)                         (eq 6)
//   dS/dx = dS/dX~ dF^-1                         (eq 18)
//   k_p = [dS/dx]' a [dS/dx] V_p, f_p = [dS/dx]' sigma V_p, V_p = det(dF) V_p,n
//                                                (eqs 14-16, a from formULstiff)
// and assembles Kt = A k_p, fint = A f_p (eqs 30-31). With form = PC the
// previously converged formulation of [Lagrangian] sec 5 is used instead:
//   k_p = [dS/dX~]' A~ [dS/dX~] V_p^n, f_p = [dS/dX~]' P~ V_p^n, P~ = tau dF^-T / Jn
//   (eqs 18, 21-23, A~ from formPCstiff); both give the same equilibrium.
// With form = SS the small-strain method of [Boundaries] sec 2 (no dF, no log):
//   eps = eps_n + sym(grad du), grad du = sum du (x) dS/dX~;  sigma = D eps (eqs 2-3, 10)
//   k_p = B' D B V_p0, f_p = B' sigma V_p0, B from dS/dX~   (eqs 6, 8-9)
//   and F stays I, so the volume stays V_p0 (updateMPs: V_p = det(F) V_p0).
// Plane strain: only the in-plane displacement gradient enters; F, b_e and
// stress are 3D.
// Kt is assembled into the sparsity of the load step (the main loop passes its
// DetMPsOut, whose Kt keeps its pattern and only has its values refilled; an empty
// Kt gets its pattern here). The second form returns a fresh result.
// Large runs take fast/detMPsFast.h instead: the same numbers, bit for bit.
// Inputs:  uvw (nDoF) displacement increment of the step · mpData · form ·
//          out (in place: Kt with the step's pattern, or empty)
// Outputs: out.fint (nDoF) · out.Kt (nDoF x nDoF) · mpData (F, sig, epsE) updated
// Tests:   tests/test_detMPs.cpp, tests/test_smallStrain.cpp (SS)
//--------------------------------------------------------------------------
#pragma once
#include "ample/solver/stiffnessPattern.h"
#include "mpData.h"

namespace ample {

struct DetMPsOut {
  Eigen::VectorXd fint;          // nodal internal forces
  SpMat Kt;                      // global tangent stiffness
  // kept for the load step by detMPsFast (fast/detMPsFast.h); detMPs leaves them alone
  std::vector<Matrix3d> bEn;     // exp(2 eps_e,n) of each point (eq 9; UL, PC)
  bool blocked = false;          // Kt's pattern is node-blocked (addNodeBlocks)
  long blockedNnz = -1;          // the pattern size that was checked
};

using PointStiffness = Eigen::Matrix<double, nD * MAXN, nD * MAXN>;  // k_p, its 2 nn x 2 nn corner

void detMPs(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData, Formulation form,
            DetMPsOut& out);
DetMPsOut detMPs(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData,
                 Formulation form = Formulation::UL);
using PointLoop = void (*)(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData, Formulation form,
                           DetMPsOut& out);  // detMPs, or a replacement of it as a whole

// the steps of the loop body, for detMPsFast:
// exp(2 eps_e,n) of a point (eq 9), its elastic left Cauchy-Green tensor at the start of the step
Matrix3d elasticLeftCG(const MaterialPoint& mp);
// the point's state (F, sigma, eps_e) from uvw; f_p added into fint; k_p into ke (eqs 5-18, 14, 16)
void addPoint(const Eigen::VectorXd& uvw, const Matrix3d& bEn, Formulation form, MaterialPoint& mp,
              Eigen::VectorXd& fint, PointStiffness& ke);
// k_p into the values of Kt's pattern (eq 30)
void assemble(const MaterialPoint& mp, const PointStiffness& ke, SpMat& Kt);

}  // namespace ample
