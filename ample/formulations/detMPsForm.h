//--------------------------------------------------------------------------
// detMPsForm — the point loop of the other formulations: PC and SS
//--------------------------------------------------------------------------
// detMPs (ample/detMPs.h) is [AMPLE]'s updated Lagrangian loop (UL). Two other
// frames of equilibrium, each a point loop as a whole, chosen once per run by
// the program through pointLoopOf:
//   PC, the previously converged formulation ([Lagrangian] sec 5, eqs 18-23):
//     equilibrium on the configuration of the step's start, dF = I + grad du
//     (eq 17), the state of detMPs (F, b_e,tr, eps_e,tr, tau, sigma: [AMPLE]
//     eqs 5-11), the first Piola-Kirchhoff-like stress P~ = tau dF^-T / Jn
//     (eq 18) with Jn = det Fn, its tangent A~ of formPCstiff ([Lagrangian]
//     eqs A.3-A.6), and k_p = G' A~ G V_p^n, f_p = G' P~ V_p^n with G of
//     dS/dX~ (no mapping) and the volume of the step's start (eqs 19-23);
//   SS, small strain ([Boundaries] sec 2, eqs 2-3, 6, 8-10): eps = eps_n +
//     sym(grad du), sigma = D eps (von Mises: the same return on the small
//     strain), k_p = G' D G V_p, f_p = G' sigma V_p with G of dS/dX~ and V_p of
//     the step's start; F stays I, so updateMPs keeps V_p = V_p0.
// G is detMPs' strain-displacement matrix, G(2k+l, 2b+k) = dS_b/dX_l, and the
// tensors are pairs (i,j) -> 2i+j (P~ is not symmetric: its second index meets
// the gradient).
// Inputs:  uvw (nDoF) · mpData · form (PC or SS)
// Outputs: out.fint (nDoF) · out.Kt (nDoF x nDoF) · mpData (F, sig, epsE)
// Tests:   tests/test_formPCstiff.cpp, tests/test_smallStrain.cpp, tests/test_pointLoops.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/detMPs.h"

namespace ample {

void detMPsForm(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData, Formulation form,
                DetMPsOut& out);

// the point loop of a formulation: detMPs (UL) or detMPsForm (PC, SS)
PointLoop pointLoopOf(Formulation form);

// the point loop of form on mpData, as detMPs(uvw, mpData, form) for any formulation
DetMPsOut detMPsOf(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData, Formulation form);

}  // namespace ample
