//--------------------------------------------------------------------------
// roundOffFloor — the level below which eq 35's residual cannot fall
//--------------------------------------------------------------------------
// Newton-Raphson drives the computed residual oobf = fext - fint(u) + frct
// (eq 31) down until it reaches the round-off of evaluating fint at a given u;
// below that the pass's correction is noise and fErr stops falling (a stall).
// This estimates that level for the point loop of detMPs ([AMPLE] eqs 14-18),
// in double precision: every operation rounds to nearest, with a relative
// error of at most the unit roundoff u = DBL_EPSILON / 2 = 1.1e-16.
//
// 1. grad du at point p (eq 17), G_ij = sum_v du_vi dS_v/dX_j, is a sum over the
//    point's nodes whose round-off is of the size of its terms, not of its
//    result: dG ~ u s_p, s_p = max_ij sum_v |du_vi| |dS_v/dX_j|. In a column
//    of n cells of h = H / n the terms are ~ U / h (U the step's displacement)
//    while G is a strain: the strain's relative error grows like n. dF = I + G
//    adds u.
// 2. stress: dsig_p ~ u (M_p (s_p + 1) + |sig_p|_max), M_p = E (1 - nu) /
//    ((1 + nu)(1 - 2 nu)) the largest elastic modulus (P wave; for von Mises
//    the elastic one bounds the tangent); the second term is the constitutive
//    function's own round-off (exp, log, the Kirchhoff stress) and that of the
//    assembly of fint (a few dozen terms f_p <= |sig| V_p |dS/dx| per dof).
// 3. nodal force (eq 16): point p puts a noise of V_p (|dS_v/dx| + |dS_v/dy|)
//    dsig_p on both dofs of node v. The points' round-off errors are not
//    correlated, so they add in quadrature at each dof, and so do the dofs in
//    the norm: |d fint| ~ sqrt(sum_dof sum_p (V_p |grad S_v|_1 dsig_p)^2).
// 4. the floor: floor = |d fint| / |fext + frct + eps|, eq 35's denominator.
//
// What it gives for the compaction column (one cell of h = H / n wide, n cells
// high; U, the settlement in a step, does not depend on n): s_p ~ U / h ~ n,
// dsig ~ E u U n / H, the noise per dof ~ h dsig ~ E u U, the same for any n,
// over ~ 2 n dofs: |d fint| ~ sqrt(n). The denominator is the base reaction,
// the weight of the column rho g H h ~ 1 / n (the nodal weights, rho g h^2
// each, add only ~ sqrt(n) h^2). So floor ~ n^1.5: x 2.83 per doubling of n.
// Measured, load step 1 of 40 (tol=1e-16 NRitMax=12; the stall is the largest
// of the last three passes, the others within 3 %):
//   nelsy      2^14      2^15      2^16      2^17
//   stall     1.57e-10  4.49e-10  1.26e-9   3.53e-9   (x 2.86, 2.81, 2.80)
//   estimate  3.3e-10   9.2e-10   2.6e-9    7.4e-9    (x 2.79, 2.83, 2.85)
// the estimate 2.05-2.10 times the stall. U and the denominator both grow with
// the load factor of the step, so the floor is the same in step 1 of 5 (2^16:
// converged at 1.26e-9 in 9 passes) and falls in later steps (2^16 with
// tol=1e-8: all 40 steps, the largest final fErr 3.7e-9).
// The round-off of the assembly and of the stress function alone (the term
// u |sig_p| of step 2 without M_p (s_p + 1)) grows like sqrt(n): 1.7e-14 at
// 2^14, 3.5e-14 at 2^16 (measured with the first term set to 0), four orders
// below the stalls: it is not what stops these runs; the cancellation in grad
// du (step 1) is.
// It is an estimate of an order of magnitude (on the side of too high: a sum's
// round-off is rarely its bound). Not included: the penalty of the implicit
// boundaries ([Boundaries]), whose K3 ~ 1e6 K1 makes a floor of its own
// (docs/implicitBoundaries.md): a stall there above 10 x this estimate is not
// named a floor by checkConverged (not measured). Computed only when a step has failed
// (checkConverged), from the state of its last pass; it changes no result.
// Inputs:  mpData (after the last pass: sig; dSvp, vp, nIN of the step) · uvw
//          (the step's nodal increment, nDoF) · load = fext + frct (+ the
//          implicit boundaries' reactions), eq 35's denominator before eps
// Outputs: the estimated floor of fErr (dimensionless)
// Tests:   tests/test_roundOffFloor.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"
#include <vector>

namespace ample {

double roundOffFloor(const std::vector<MaterialPoint>& mpData, const Eigen::VectorXd& uvw,
                     const Eigen::VectorXd& load);

}  // namespace ample
