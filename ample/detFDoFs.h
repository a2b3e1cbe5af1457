//--------------------------------------------------------------------------
// detFDoFs — free degrees of freedom of the background grid
//--------------------------------------------------------------------------
// Seed 002 sec 4 and sec 5.3: the degrees of freedom of the nodes of active
// cells (eInA, cells linked to a point) less those with a Dirichlet
// condition. Nodes that no point supports are eliminated this way.
// Inputs:  mesh (etpl, eInA, bc, nodes)
// Outputs: fd (ascending list of free degrees of freedom)
// Tests:   tests/test_detFDoFs.cpp
//--------------------------------------------------------------------------
#pragma once
#include "mpData.h"

namespace ample {

std::vector<int> detFDoFs(const Mesh& mesh);

}  // namespace ample
