//--------------------------------------------------------------------------
// elemMPinfoCPDI — elemMPinfo for a run with CPDI points, on either mesh
//--------------------------------------------------------------------------
// [CPDI] sec 2 (iii)-(iv). Replaces the core's elemMPinfo as a whole where the
// program chooses it (a run with CPDI points; setups/program/run.cpp). Per CPDI
// point (cpdiPointInfo): the cells that hold its four domain corners (a corner on
// a cell edge goes into the cell on the domain's side of it; on the grid a corner
// past the grid edge into the cell at the edge, on a general mesh a corner outside
// the mesh into cornerCell's cell), their nodes (nodesForMP), S_vp and dS_vp of
// CPDI1 / CPDI2 from the basis of each node at the corners (cpdiBasis: SvpCPDI1,
// SvpCPDI2 of cornerBasis), its null nodes unlinked (dropNullNodes: a corner on
// the far edge of its cell, e.g. on the base y = 0, gives N = 0 there for the nodes
// of the cell's upper edge). Any other point as the loop of its mesh takes it
// (pointInfo on the grid, meshPointInfo on a general mesh). Then the active cells.
// Inputs:  mesh · mpData (mpC, mpType, cpdi; lp of the others) · keepCells (FE mode)
// Outputs: mpData (eIN, ne, nIN, nn, Svp, dSvp) · mesh.eInA (general mesh: search);
//          RunError naming the point that left the grid or mesh
// Tests:   tests/test_cpdi.cpp, tests/test_detFDoFs.cpp, tests/test_mesh.cpp
//--------------------------------------------------------------------------
#pragma once
#include "cornerBasis.h"

namespace ample {

void elemMPinfoCPDI(Mesh& mesh, std::vector<MaterialPoint>& mpData, bool keepCells = false);

// its parts (for elemMPinfoFast)
void cpdiPointInfo(const Mesh& mesh, MaterialPoint& mp, size_t p);  // CPDI point p
void cpdiBasis(MaterialPoint& mp, const Corners& x, const CornerBasis& S);  // Svp, dSvp from S(v, c)

}  // namespace ample
