//--------------------------------------------------------------------------
// elemMPinfo — cells, nodes, basis functions and gradients of every point
//--------------------------------------------------------------------------
// [AMPLE] sec 4, table 1: once at the start of each load step. GIMP/MPM points
// take the cells their domain overlaps (elemForMP), CPDI points the cells of their
// four corners ([CPDI] sec 2 (iii)); on a general mesh meshElemForMP and
// meshMPMbasis (docs/meshes.md). Per point: its cells, its nodes (nodesForMP),
// S_vp and dS_vp (MPMbasis; nodes with S = dS = 0 unlinked: dropNullNodes). Then
// the active cells. keepCells (FE mode): a point keeps the cell it has, no search.
// Large runs take fast/elemMPinfoFast.h instead: the same result, on threads.
// Inputs:  mesh · mpData (mpC, lp, mpType, cpdi; eIN, ne when keepCells) · keepCells
// Outputs: mpData (eIN, ne, nn; nIN, Svp, dSvp) · mesh.eInA (nels)
// Tests:   tests/test_basis.cpp, tests/test_pointShares.cpp
//--------------------------------------------------------------------------
#pragma once
#include "mpData.h"

namespace ample {

void elemMPinfo(Mesh& mesh, std::vector<MaterialPoint>& mpData, bool keepCells = false);
int dropNullNodes(MaterialPoint& mp);  // unlink nodes with S = 0 and dS = 0; returns the new nn
using BasisLoop = void (*)(Mesh& mesh, std::vector<MaterialPoint>& mpData, bool keepCells);  // or a replacement

// the steps of elemMPinfo for one point (p: its index, for messages), for elemMPinfoFast
void pointCells(const Mesh& mesh, MaterialPoint& mp, size_t p, bool keepCells);  // eIN, ne
void pointBasis(const Mesh& mesh, MaterialPoint& mp);                            // nIN, nn, Svp, dSvp
void markActiveCells(Mesh& mesh, const std::vector<MaterialPoint>& mpData);

}  // namespace ample
