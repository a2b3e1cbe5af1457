//--------------------------------------------------------------------------
// updateDomain — the other domain updates: [Lagrangian]'s and CPDI's
//--------------------------------------------------------------------------
// The hook updateDomain of updateMPs, which the program passes in place of the
// core's updateGIMPDomain ([AMPLE] eq 34) when a setup has CPDI points or asks
// for another domainUpdate.
// GIMP half lengths l_p by the chosen method ([Lagrangian] sec 6.4, table 2):
//   None       l = l0
//   DetF       l_i = l0_i det(F)^(1/nD)                               (eq 32)
//   Fii        l_i = l0_i |F_ii|                                      (eq 33)
//   Uii        l_i = l0_i U_ii, U = sqrt(F'F)   (eq 34; default: updateGIMPDomain)
//   Corner     corners moved by the grid (eq 35), half lengths from the edge
//              midpoints (eq 36), scaled to the volume det(F) V0 (eq 37)
//   FiiVol     l_i = l0_i |F_ii| (det F / prod_j |F_jj|)^(1/nD)          (eq 38)
//   FiiVolInc  l_i = ln_i |dF_ii| (det dF / prod_j |dF_jj|)^(1/nD), dF = F Fn^-1 (eq 39)
// CPDI1: s = F s0, t = F t0; CPDI2: corners moved by the grid basis, x_c +=
// sum_v N_v(x_c) du_v ([CPDI] sec 2 (vii)), volume = area of the corners;
// for CPDI lp is set to half the bounding box of the domain (output only).
// Standard MPM points have no domain and are left alone.
// Called before the point moves: corners are taken at the start of the step.
// Inputs:  mesh · uvw (nDoF) · method · mp (mpC at the start of the step, F, Fn,
//          lp, lp0, nIN, Svp; CPDI: cpdi->st0, cpdi->xc)
// Outputs: mp.lp; CPDI: mp.cpdi->st, mp.cpdi->xc (and mp.vp for CPDI2)
// Tests:   tests/test_updateDomain.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"

namespace ample {

void updateDomain(const Mesh& mesh, const Eigen::VectorXd& uvw, DomainUpdate method,
                  MaterialPoint& mp);

}  // namespace ample
