//--------------------------------------------------------------------------
// updateMPs — material point positions, volumes, domains and state at step end
//--------------------------------------------------------------------------
// [AMPLE] sec 3.4:
//   x_p = X~_p + sum_v S_vp du_v     (eq 33), also the total displacement u
//   V_p = det(F) V_p^0               (eq 15)
//   l_p,i = l_p0,i U_ii, U = sqrt(F'F)   (eq 34, updateGIMPDomain: GIMP points;
//                                     standard MPM points have no domain)
//   Fn = F, eps_e,n = eps_e          (converged state for the next step)
// The domain update is a parameter: the program passes the other ones (the
// hook updateDomain: [Lagrangian] eqs 32-39, CPDI's corners; ample/domains/).
// Inputs:  mesh · uvw (nDoF) converged displacement increment of the step ·
//          mpData · [updateDomain]
// Outputs: mpData (mpC, u, vp, lp, Fn, epsEn; with another updateDomain also
//          cpdi->st, cpdi->xc) updated
// moveMesh (finite element mode, Analysis::fem): coord += uvw, so the mesh
//   follows the body and every point keeps its cell and local coordinates
//   (x_p = sum_v S_vp x_v before and after): updated Lagrangian FEM with the
//   points as integration points. MPM resets the mesh instead (coord kept).
// Tests:   tests/test_updateMPs.cpp, tests/test_femode.cpp
//--------------------------------------------------------------------------
#pragma once
#include "mpData.h"

namespace ample {

// eq 34 for a GIMP point (called before it moves); nothing for the others
void updateGIMPDomain(const Mesh& mesh, const Eigen::VectorXd& uvw, MaterialPoint& mp);
// a point's domain at the end of the step: updateGIMPDomain here; the program's hooks
// (hooks.h) choose another domain update (CPDI, domainUpdate=)
struct UpdateDomain {
  virtual void updateDomain(const Mesh& mesh, const Eigen::VectorXd& uvw, MaterialPoint& mp) const {
    updateGIMPDomain(mesh, uvw, mp);
  }
};

void updateMPs(const Mesh& mesh, const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData,
               const UpdateDomain& domains = UpdateDomain());
void moveMesh(Mesh& mesh, const Eigen::VectorXd& uvw);

}  // namespace ample
