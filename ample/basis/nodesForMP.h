//--------------------------------------------------------------------------
// nodesForMP — unique list of the nodes of the cells linked to a point
//--------------------------------------------------------------------------
// [AMPLE] table 1. nIN has room for MAXN nodes (a point's nIN); it returns nn.
// Inputs:  etpl (nels x 4, or x 3 for triangles) · eIN (ne cells)
// Outputs: nIN (nn nodes, ascending) · number of nodes nn
// Tests:   tests/test_grid.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"

namespace ample {

int nodesForMP(const Mesh& mesh, const std::array<int, MAXE>& eIN, int ne, int* nIN);

}  // namespace ample
