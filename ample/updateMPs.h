//--------------------------------------------------------------------------
// updateMPs — material point positions, volumes, domains and state at step end
//--------------------------------------------------------------------------
// [AMPLE] sec 3.4:
//   x_p = X~_p + sum_v S_vp du_v     (eq 33), also the total displacement u
//   V_p = det(F) V_p^0               (eq 15)
//   domains: updateDomain (GIMP eq 34 by default, or [Lagrangian] eqs 32-39;
//            CPDI1/CPDI2 of [CPDI]), nothing for standard MPM points
//   Fn = F, eps_e,n = eps_e          (converged state for the next step)
// Inputs:  mesh · uvw (nDoF) converged displacement increment of the step ·
//          method (GIMP domain update) · mpData
// Outputs: mpData (mpC, u, vp, lp, cpdi->st, cpdi->xc, Fn, epsEn) updated
// moveMesh (finite element mode, Analysis::fem): coord += uvw, so the mesh
//   follows the body and every point keeps its cell and local coordinates
//   (x_p = sum_v S_vp x_v before and after): updated Lagrangian FEM with the
//   points as integration points. MPM resets the mesh instead (coord kept).
// Tests:   tests/test_updateMPs.cpp, tests/test_femode.cpp
//--------------------------------------------------------------------------
#pragma once
#include "mpData.h"

namespace ample {

void updateMPs(const Mesh& mesh, const Eigen::VectorXd& uvw, DomainUpdate method,
               std::vector<MaterialPoint>& mpData);
void moveMesh(Mesh& mesh, const Eigen::VectorXd& uvw);

}  // namespace ample
