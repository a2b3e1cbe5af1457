//--------------------------------------------------------------------------
// addPoint — one point of the fast point loop: its state, f_p and k_p, unrolled
//--------------------------------------------------------------------------
// The body of detMPsFast's loop for the three formulations, the equations of
// the point loops it replaces (ample/detMPs.cpp for UL, ample/formulations/ for
// PC and SS) written for speed:
//   dF = I + sum_v du_v (x) dS_v/dX~ node by node (eq 17); b_e,tr = dF b_e,n dF'
//   (eq 8) with b_e,n = exp(2 eps_e,n) given (eq 9, elasticLeftCG, once a load
//   step); one closed-form decomposition of b_e,tr for ln(b_e,tr)/2 (eq 10) and
//   the tangent (inPlaneEigen, dLogdB2D); the constitutive model (eqs 5, 11);
//   sigma = tau / det F (eq 6); UL: A of formULstiff2D, dS/dx = dF^-T dS/dX~
//   (eq 18), V_p = det(dF) V_p^n (eq 15); PC: [Lagrangian] eqs 18-23, A of
//   formPCstiff2D, P~ = tau dF^-T / Jn; SS: [Boundaries] eqs 2-3, 8-10, A = D;
//   then f_p (eq 16) and k_p (eq 14) with the products g_jkl = dS_a/dx_j A_ijkl
//   formed once per node a and direction i: half the multiplications of the
//   double sum. The sums and their order are those of the runs before the core
//   loop was written as [AMPLE]'s G' A G (2026-12-06): large runs keep their
//   numbers bit for bit. They differ from the core's in round-off only
//   (tests/test_pointLoops.cpp: within 1e-12).
// Inputs:  uvw (nDoF) · bEn = exp(2 eps_e,n) (UL, PC; unused for SS) · form · mp
// Outputs: mp (F, sig, epsE) · fint (f_p added) · ke (k_p, its 2 nn x 2 nn corner)
// Tests:   tests/test_pointLoops.cpp, tests/test_detMPs.cpp (threads)
//--------------------------------------------------------------------------
#pragma once
#include "ample/detMPs.h"

namespace ample {

// exp(2 eps_e,n) of a point (eq 9), its elastic left Cauchy-Green tensor at the start of the step
Matrix3d elasticLeftCG(const MaterialPoint& mp);
// the point's state (F, sigma, eps_e) from uvw; f_p added into fint; k_p into ke (eqs 5-18, 14, 16)
void addPoint(const Eigen::VectorXd& uvw, const Matrix3d& bEn, Formulation form, MaterialPoint& mp,
              Eigen::VectorXd& fint, PointStiffness& ke);

}  // namespace ample
