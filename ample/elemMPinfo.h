//--------------------------------------------------------------------------
// elemMPinfo — cells, nodes, basis functions and gradients of every point
//--------------------------------------------------------------------------
// [AMPLE] sec 4, table 1: once at the start of each load step, for the standard
// MPM and GIMP points of the regular grid. Per point (pointInfo): the cells its
// domain overlaps (elemForMP), their nodes (nodesForMP), S_vp and dS_vp
// (MPMbasis). Then the active cells (markActiveCells). CPDI points and general
// meshes have loops of their own that replace this one as a whole (BasisLoop:
// ample/cpdi/elemMPinfoCPDI.h, ample/meshes/elemMPinfoMesh.h; large runs
// ample/fast/elemMPinfoFast.h), chosen by the program (setups/program/run.cpp).
// Inputs:  mesh (regular grid) · mpData (mpC, lp, mpType)
// Outputs: mpData (eIN, ne, nIN, nn, Svp, dSvp) · mesh.eInA (nels); RunError
//          naming the point that left the grid or whose domain grew too large
// Tests:   tests/test_basis.cpp, tests/test_pointShares.cpp
//--------------------------------------------------------------------------
#pragma once
#include "errors.h"
#include "mpData.h"

namespace ample {

void elemMPinfo(Mesh& mesh, std::vector<MaterialPoint>& mpData);

// its parts, which the loops that replace it reuse
void pointInfo(const Mesh& mesh, MaterialPoint& mp, size_t p);  // point p: eIN, ne, nIN, nn, Svp, dSvp
void pointNodes(const Mesh& mesh, MaterialPoint& mp);             // nIN, nn from eIN, ne; Svp, dSvp zeroed
void markActiveCells(Mesh& mesh, const std::vector<MaterialPoint>& mpData);  // eInA
RunError atPoint(size_t p, const RunError& e);                  // e, its message naming point p
// a loop that replaces elemMPinfo as a whole (keepCells: the finite element mode's, fem=1)
using BasisLoop = void (*)(Mesh& mesh, std::vector<MaterialPoint>& mpData, bool keepCells);

}  // namespace ample
