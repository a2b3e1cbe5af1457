//--------------------------------------------------------------------------
// detMPs — internal force and stiffness of all material points (the point loop)
//--------------------------------------------------------------------------
// For each point ([AMPLE] sec 2): dF = I + sum du (x) dS/dX~ (eq 17), F = dF Fn,
// b_e,tr = dF exp(2 eps_e,n) dF' (eqs 7-9), eps_e,tr = ln(b_e,tr)/2 (eq 10), tau, D
// from Hooke3d / VMconst (eqs 5, 11), sigma = tau / det F (eq 6); k_p, f_p (eqs 14-18);
// then Kt = A k_p, fint = A f_p (eqs 30-31). form = PC: [Lagrangian] eqs 18-23;
// form = SS: small strain, [Boundaries] eqs 2-3, 6, 8-10 (docs/algorithm.md).
// Inputs:  uvw (nDoF) the step's displacement increment · mpData · form
// Outputs: out.fint (nDoF) · out.Kt (nDoF x nDoF) · mpData (F, sig, epsE)
// Tests:   tests/test_detMPs.cpp, tests/test_formULstiff.cpp, tests/test_smallStrain.cpp
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

// the steps of the loop body, for detMPsFast:
// exp(2 eps_e,n) of a point (eq 9), its elastic left Cauchy-Green tensor at the start of the step
Matrix3d elasticLeftCG(const MaterialPoint& mp);
// the point's state (F, sigma, eps_e) from uvw; f_p added into fint; k_p into ke (eqs 5-18, 14, 16)
void addPoint(const Eigen::VectorXd& uvw, const Matrix3d& bEn, Formulation form, MaterialPoint& mp,
              Eigen::VectorXd& fint, PointStiffness& ke);
// k_p as entries (row, column, value) of Kt (eq 30), appended to Kt's list
void assemble(const MaterialPoint& mp, const PointStiffness& ke, std::vector<Eigen::Triplet<double>>& Kt);

}  // namespace ample
