//--------------------------------------------------------------------------
// detMPs — internal force and stiffness of all material points (the point loop)
//--------------------------------------------------------------------------
// [AMPLE] sec 2, the updated Lagrangian form, as AMPLE's detMPs.m: for each point
//   dF = I + sum_v du_v (x) dS_v/dX~                     eq 17
//   F = dF Fn,  b_e,tr = dF exp(2 eps_e,n) dF'            eqs 7-9
//   eps_e,tr = ln(b_e,tr) / 2                             eq 10
//   tau, D, eps_e = Hooke3d or VMconst(eps_e,tr)          eqs 5, 11
//   sigma = tau / det F                                   eq 6
//   A = formULstiff(F, D, sigma, b_e,tr)                  [Lagrangian] eq A.1 (4 x 4 in plane)
//   G: the strain-displacement matrix of dS/dx = dF^-T dS/dX~ (eq 18), G u_p = grad du
//   V_p = det(dF) V_p^n                                   eq 15
//   k_p = G' A G V_p,  f_p = G' sigma V_p                 eqs 14, 16
// then Kt = A k_p, fint = A f_p (eqs 30-31). The other formulations, PC
// ([Lagrangian] eqs 18-23) and SS ([Boundaries] sec 2), are point loops of their
// own (ample/formulations/), which the program chooses.
// Inputs:  uvw (nDoF) the step's displacement increment · mpData · form (UL)
// Outputs: out.fint (nDoF) · out.Kt (nDoF x nDoF) · mpData (F, sig, epsE)
// Tests:   tests/test_detMPs.cpp, tests/test_pointLoops.cpp, tests/test_formULstiff.cpp
//--------------------------------------------------------------------------
#pragma once
#include <Eigen/SparseCore>
#include "mpData.h"
#include <memory>

namespace ample {

struct PointLoopPlan;          // detMPsFast's (fast/detMPsFast.h)

struct DetMPsOut {
  Eigen::VectorXd fint;          // nodal internal forces
  SpMat Kt;                      // global tangent stiffness
  std::shared_ptr<PointLoopPlan> plan;  // kept for the load step by detMPsFast; detMPs leaves it alone
};

using PointStiffness = Eigen::Matrix<double, nD * MAXN, nD * MAXN>;  // k_p, its 2 nn x 2 nn corner

void detMPs(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData, Formulation form,
            DetMPsOut& out);
DetMPsOut detMPs(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData,
                 Formulation form = Formulation::UL);
using PointLoop = void (*)(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData, Formulation form,
                           DetMPsOut& out);  // detMPs, or a replacement of it as a whole

}  // namespace ample
