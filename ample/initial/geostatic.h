//--------------------------------------------------------------------------
// geostatic — the initial K0 stress of a body under gravity, in balance with its weight
//--------------------------------------------------------------------------
// With geostatic=on (Analysis::geostatic, the common parameters geostatic and K0)
// every point starts from the stress of a layer at rest under its own weight:
//   sigma_yy = -rho g d,  sigma_xx = sigma_zz = K0 sigma_yy,  sigma_xy = 0,
// rho = m_p / V0_p the point's density, g = an.g, d = y_top - y_p its depth below
// the top of the body above it. y_top: the highest domain top among the points
// whose centre lies in the same column of grid cells (the cells of one x range):
// y + lp_y for GIMP, y + sqrt(V) / 2 for the others (half the side of a square of
// the point's area). So a body whose top is level within each column (a layer,
// the compaction column, a block) is at rest; one with a sloping surface is
// stepped, one column at a time.
// The elastic strain is set consistently (F = I at the start, so Kirchhoff tau =
// sigma and Hencky eps_e = D^-1 tau, eq 5):
//   eps_ii = ((1 + nu) sigma_ii - nu (sigma_xx + sigma_yy + sigma_zz)) / E,
//   gamma_xy = sigma_xy / G = 0,
// stored as epsEn and epsE, so the first load step starts from it (detMPs).
// A von Mises point whose state lies beyond its yield surface, rho = sqrt(2 J2)
// = sqrt(2/3) |1 - K0| |sigma_yy| > rho_y, is refused (InputError naming K0 and
// the K0 this body allows, [1 - m, 1 + m] with m = min rho_y / (sqrt(2/3) |sigma_yy|)).
// The load steps then carry the full weight from load step 1 (selfWeight, added
// by the run's stepTerms hook, setups/program/run.cpp): gravity is not ramped.
// Inputs:  an (mesh: the regular grid; mpData: positions, domains, mass, mCst, cmType;
//          g; geostatic; K0)
// Outputs: an.mpData's sig, epsE, epsEn · selfWeight: the nodal weight
//          sum_p [S_vp]^T m_p {0, -g} (no point forces), eq 27
// Errors:  InputError: no gravity (g = 0), not the regular grid, a von Mises point
//          beyond yield
// Tests:   tests/test_geostatic.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/analysis.h"

namespace ample {

// eps_e = D^-1 sigma of isotropic elasticity (E, nu), engineering shear strains
Vector6d elasticStrainOf(const Vector6d& sigma, double E, double nu);
// the K0 stress and its elastic strain in every point of an (see above)
void applyGeostatic(Analysis& an);
// the nodal weight of the points (eq 27 without point forces), from their basis of the step
Eigen::VectorXd selfWeight(int nDoF, double g, const std::vector<MaterialPoint>& mpData);

}  // namespace ample
