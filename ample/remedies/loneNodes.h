//--------------------------------------------------------------------------
// loneNodes — detFDoFs less the redundant dofs of lone nodes (lone=1; lone=2 after a failure)
//--------------------------------------------------------------------------
// detFDoFs' free set, from which two rules remove redundant dofs:
// A node reached through one CPDI corner only:
//   a node linked to one point p only, with the grid basis N_v non-zero at
//   one corner c of p only, has S_v = w_c N_v(x_c) and dS_v = N_v(x_c) g_c
//   ([CPDI] sec 2 (iv)), so the displacements u_v of all such nodes of
//   (p, c) enter the point's dF, position and forces only through
//   sum_v N_v(x_c) u_v. With two or more of them free in a direction the
//   stiffness is singular (a corner poking into an empty cell). Per (p, c)
//   and direction one free dof is kept (the node with the largest S_v); the
//   others are left out of the system, which changes no point quantity: the
//   residual of each is N_v(x_c) times that of the kept one, zero at
//   convergence.
// The same holds for a GIMP or MPM point's lone nodes (linked to it alone): they
//   enter its position, dF and forces only through a_v = (S_v, dS_v/dx, dS_v/dy),
//   three numbers per direction, so more than three lone dofs in a direction, or
//   any whose a_v is a combination of the others', are redundant. The common case:
//   a GIMP domain poking into an empty row of cells across a grid line links three
//   nodes of that row, with S_v = Sx_v Sy and dS_v = (dSx_v Sy, Sx_v dSy): two
//   combinations of three, a zero-energy mode per direction, whose LU pivot is
//   round-off (zero or not by the summation order, i.e. the thread count). Per
//   point and direction the lone dofs are taken by decreasing |S_v| and one is
//   kept only if its a_v (each component scaled by its largest magnitude over the
//   point's nodes) is further than 1e-10 |a_v| from the span of those kept
//   (exactly dependent vectors come out at ~1e-16). The decision reads per-point
//   data only (link counts, S_v, dS_v), never an assembled sum.
// Both rules drop a dof only where the point is the node's only stiffness: a node
//   that the ghost penalty or an implicit boundary reaches (others) is not lone.
// lone=0 leaves both out (detFDoFs, [AMPLE]'s free set): the 2x2 beam (a=2 mp=2) then
//   stops in load step 8 as in the paper (12 with the rules).
// Inputs:  mesh (bc, nodes, coord, h) · mpData (nIN, nn, Svp, dSvp, corners)
//          · others (the ghost penalty's and the implicit boundaries' K; null or empty: none)
// Outputs: fd (ascending list of free degrees of freedom)
// Tests:   tests/test_detFDoFs.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/detFDoFs.h"

namespace ample {

// stiffness added to Kt besides the points' (ghost penalty, implicit boundaries): a node
// with an entry in a column of one of them is never lone (null pointers, empty: none)
using StiffnessSources = std::vector<const SpMat*>;

std::vector<int> detFDoFsLone(const Mesh& mesh, const std::vector<MaterialPoint>& mpData,
                              const StiffnessSources& others = {});

}  // namespace ample
