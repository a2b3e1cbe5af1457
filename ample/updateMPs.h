//--------------------------------------------------------------------------
// updateMPs — material point positions, volumes, domains and state at step end
//--------------------------------------------------------------------------
// Seed 002 sec 3.4:
//   x_p = X~_p + sum_v S_vp du_v     (eq 33), also the total displacement u
//   V_p = det(F) V_p^0               (eq 15)
//   GIMP: l_p,i = l_p,i^0 U_ii       (eq 34), U = sqrt(F'F) the material stretch
//   Fn = F, eps_e,n = eps_e          (converged state for the next step)
// Standard MPM points (lp = 0) do no domain work.
// Inputs:  uvw (nDoF) converged displacement increment of the step · mpData
// Outputs: mpData (mpC, u, vp, lp, Fn, epsEn) updated
// Tests:   tests/test_updateMPs.cpp
//--------------------------------------------------------------------------
#pragma once
#include "mpData.h"

namespace ample {

Matrix3d stretchTensor(const Matrix3d& F);  // U = sqrt(F'F), the right stretch tensor
void updateMPs(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData);

}  // namespace ample
