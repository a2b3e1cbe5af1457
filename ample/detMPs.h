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
// Kt is assembled into the sparsity of the load step (the points link the
// same nodes in every iteration): the main loop passes its DetMPsOut, whose Kt
// from the last pass (or stiffnessPattern, once per step) keeps its pattern
// and only has its values refilled, in place (an Eigen 3.4 SparseMatrix has
// no move constructor: a result returned by value would copy it every pass).
// An empty Kt gets its pattern here. The second form returns a fresh result.
// Also kept for the step: exp(2 eps_e,n) of each point (eq 9, out.bEn) and
// whether Kt's pattern is node-blocked (then addNodeBlocks assembles).
// With OpenMP (CMake option AMPLE_OPENMP) and at least 2048 points per thread
// (pointShares.h) the point loop runs on OMP_NUM_THREADS threads, each owning a
// range of nodes (their rows of fint, their columns of Kt) and adding the points
// that link them in point order: the serial loop's numbers, bit for bit.
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
  // kept for the load step (the main loop's DetMPsOut lives for one step):
  std::vector<Matrix3d> bEn;     // exp(2 eps_e,n) of each point (eq 9; UL, PC)
  bool blocked = false;          // Kt's pattern is node-blocked (addNodeBlocks)
  long blockedNnz = -1;          // the pattern size that was checked
};

using PointStiffness = Eigen::Matrix<double, nD * MAXN, nD * MAXN>;  // k_p, its 2 nn x 2 nn corner

// exp(2 eps_e,n) of every point (eq 9), once per load step
std::vector<Matrix3d> elasticLeftCG(const std::vector<MaterialPoint>& mpData);

void detMPs(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData, Formulation form,
            DetMPsOut& out);
DetMPsOut detMPs(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData,
                 Formulation form = Formulation::UL);

}  // namespace ample
