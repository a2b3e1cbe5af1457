//--------------------------------------------------------------------------
// elemMPinfo — cells, nodes, basis functions and gradients of every point
//--------------------------------------------------------------------------
// [AMPLE] sec 4, table 1: called once at the start of each load step, with
// the positions and domains at the start of the step (X~); marks the active
// cells (those linked to any point) for detFDoFs. A general mesh (docs/meshes.md)
// gets its bucket grid rebuilt first (buildCellSearch: a setup may move the nodes). GIMP/MPM points take the
// cells their domain overlaps (elemForMP); CPDI points the cells holding their
// four domain corners ([CPDI] sec 2 (iii)). A node of those cells whose basis
// value and gradient are both zero at the point is not linked (dropNullNodes).
// keepCells (the finite element mode, Analysis::fem): a point that has its
// cell from an earlier step keeps it without a search, as an integration point
// keeps its element however the element distorts (a non-convex cell fails the
// search's edge test but its isoparametric map still holds at the point).
// The regular grid and a general mesh each have their own path, chosen once
// here: elemForMP and MPMbasis on the grid, meshElemForMP and meshMPMbasis on
// a general mesh.
// The basis goes into the basis arena (basisArena.h), in three passes: each
// point's cells and the number of their nodes; a slice of that many entries each,
// in point order (roomForBasis: the arena of the last step is reused when only
// these points hold it, so nothing is allocated per point); the nodes, S_vp and
// dS_vp into the slices (a null node dropped leaves its entry unused, zero).
// With OpenMP and at least 2048 points a thread (pointShares.h) the points of
// passes one and three are shared out over the threads (each writes only its own
// points and slices; the same result as serially, bit for bit); the active cells
// are marked after.
// Inputs:  mesh · mpData (mpC, lp, mpType, cpdi; eIN, ne when keepCells) · keepCells
// Outputs: mpData (eIN, ne, nn; nIN, Svp, dSvp: views of the arena, basis) ·
//          mesh.eInA (nels)
// Tests:   tests/test_basis.cpp, tests/test_basisArena.cpp (threaded: tests/test_pointShares.cpp)
//--------------------------------------------------------------------------
#pragma once
#include "mpData.h"

namespace ample {

void elemMPinfo(Mesh& mesh, std::vector<MaterialPoint>& mpData, bool keepCells = false);
int dropNullNodes(MaterialPoint& mp);  // unlink nodes with S = 0 and dS = 0; returns the new nn

}  // namespace ample
