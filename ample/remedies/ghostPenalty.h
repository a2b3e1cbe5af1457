//--------------------------------------------------------------------------
// ghostPenalty — ghost stabilisation of the cells at the edge of the body
//--------------------------------------------------------------------------
// A remedy for nearly empty cells, after Burman's ghost penalty
// (E. Burman, C. R. Acad. Sci. Paris 348, 2010) as used for the implicit MPM by
// W.M. Coombs, "Ghost stabilisation of the material point method for stable
// quasi-static and dynamic analysis of large deformation problems", IJNME
// 124 (2023). For every face F shared by two active cells of which at least
// one is an edge cell (it has an inactive neighbour or lies on the grid edge):
//   K_gp = sum_F gamma E h int_F [[du/dn]] . [[dv/dn]] ds,
// the jump of the normal derivative of the bi-linear grid interpolation across
// F (2-point Gauss along F), E the largest Young's modulus of the points. The
// penalty acts on the displacement increment of the step: fint += K_gp uvw.
// Off (gamma = 0) by default, so the paper's algorithm is unchanged. With gamma > 0
// it is used only from the first load step that fails without it (retryStep
// switches it on, Analysis::ghostFrom): the nearly free nodes of barely touched
// cells (stiffness ~1e-12 E) are pinned by any gamma E above their stiffness, which
// moved a converging run's answer by up to 0.6 % for gamma >= 1e-8 and stopped the
// beam at gamma = 1e-12, so a run that converges without it never sees it.
// addGhostPenalty is its one line in the Newton-Raphson loop, after detMPs:
// Kt += K_gp, fint += K_gp uvw; it does nothing when K_gp is empty (ghost = 0).
// Inputs:  mesh (etpl, eInA, nelsx, nelsy, h, coord) · gamma · E | K_gp · uvw
// Outputs: K_gp (nDoF x nDoF), empty when no face qualifies | Kt, fint
// The faces follow the regular grid: a general mesh gets an InputError.
// Tests:   tests/test_robustness.cpp, tests/test_mesh.cpp (refusal)
//--------------------------------------------------------------------------
#pragma once
#include "ample/solver/stiffnessPattern.h"
#include "ample/mpData.h"

namespace ample {

SpMat ghostPenalty(const Mesh& mesh, double gamma, double E);
void addGhostPenalty(const SpMat& Kgp, const Eigen::VectorXd& uvw, SpMat& Kt, Eigen::VectorXd& fint);

}  // namespace ample
