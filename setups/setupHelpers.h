//--------------------------------------------------------------------------
// setupHelpers — material point generation and boundary conditions for setups
//--------------------------------------------------------------------------
// Seed 002 sec 5.2 (fig 11): points are placed mp x mp per cell of a block of
// cells (detMpPos local positions mapped by shapefunc), cell by cell (x
// fastest); each gets the domain half lengths h/(2 mp) (GIMP; 0 for MPM),
// volume (h_x/mp)(h_y/mp) (unit thickness) and mass rho V.
// Inputs:  block corner (x0, y0), its cells (nelsx, nelsy), spacing h,
//          parameters mp, mpType, cmType, E, nu, rhoY · density rho
// Outputs: points appended to mpData; fixDofs adds Dirichlet conditions
// Tests:   tests/test_ample.cpp (setups run), tests/test_detMPs.cpp
//--------------------------------------------------------------------------
#pragma once
#include "setups.h"
#include <functional>

namespace ample {

// an Analysis with the settings every setup shares: lstps, tol, NRitMax,
// formulation, domainUpdate (g is set by the setups that have gravity)
Analysis baseAnalysis(const Params& P);

void fillBlock(std::vector<MaterialPoint>& mpData, const Vector2d& corner, int nelsx, int nelsy,
               const Vector2d& h, const Params& P, double rho);

// constrain direction i (0 = x, 1 = y) of every node where `where(X, Y)` holds
void fixDofs(Mesh& mesh, int i, const std::function<bool(double, double)>& where,
             double value = 0.0);

}  // namespace ample
