//--------------------------------------------------------------------------
// detMPsFbar — detMPs with F-bar (UL, PC) or its small-strain B-bar (SS): the
// point loop of locking=Fbar, against volumetric locking
//--------------------------------------------------------------------------
// The bilinear basis cannot deform a cell at constant volume at every point of
// it, so nearly incompressible elasticity and von Mises (isochoric) flow lock.
// F-bar (de Souza Neto, Peric, Dutko & Owen 1996; for implicit MPM, Coombs,
// Charlton, Cortis & Augarde, CMAME 2018) gives every point of a patch the
// patch's volume change. The patch is the grid cell that holds the point's
// centre (one volume per cell, as the Q1/P0 element). Within a load step:
//   dJ_p = det dF_p,  dJbar_c = sum_c dJ_q v_q^n / sum_c v_q^n  (the cell's
//   volume now over its volume at the step's start),
//   dFbar_p = (dJbar_c / dJ_p)^(1/2) dF_p     (the in-plane block; zz stays 1)
// and the point is then worked as in detMPs with dFbar for dF: F = dFbar Fn,
// b_e,tr = dFbar b_e,n dFbar' (eqs 7-11), sigma = tau / det F; the internal
// force is f = sum_p B_p' sigma_p v_p with the point's real spatial gradients
// dS/dx = dF^-T dS/dX~ and real volume v_p = dJ_p v_p^n (eqs 16, 18).
// Consistent tangent (the linearisation of that f; docs/locking.md):
//   k = sum_p B_p' (A_p - Q_p (x) I) B_p v_p + sum_c (sum_p B_p' Q_p v_p) (x) wbar_c
//   Q_p = A_p:I / 2 - sigma_p / 2,   wbar_c = sum_c v_q dS_q/dx / sum_c v_q
// with A_p the UL tangent (formULstiff2D) at Fbar: the second sum couples the
// nodes of a cell's points, and Kt is not symmetric. SS (B-bar): theta = tr grad du,
// gradbar du = grad du + (thetabar_c - theta_p) I / 2 (the same average, linearised),
// Q_p = A_p:I / 2 with A_p = D, volumes V_p. PC is the same equations written on the
// step's start configuration: it takes this UL form (the same numbers to round-off).
// A cell with one point: Fbar = F, and the two coupling terms cancel (detMPs).
// Homogeneous deformation: dJ equal in the cell, Fbar = F (the patch test).
// Inputs:  mesh (the regular grid: cells by its spacing) · uvw (nDoF) · mpData ·
//          form
// Outputs: out.fint · out.Kt (nDoF x nDoF) · mpData (F = Fbar Fn, sig, epsE)
// Tests:   tests/test_fbar.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/detMPs.h"

namespace ample {

void detMPsFbar(const Mesh& mesh, const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData,
                Formulation form, DetMPsOut& out);

// the grid cell that holds x: X_k < x <= X_k+1 in each direction, as elemForMP puts a
// standard point (clamped to the grid)
int cellHolding(const Mesh& mesh, const Vector2d& x);

// why locking=Fbar cannot run this analysis ("" when it can): a general mesh (its cells are
// not found by the spacing) or the finite element mode
std::string fbarRefusal(const Mesh& mesh, bool fem);

}  // namespace ample
