//--------------------------------------------------------------------------
// detFDoFs — free degrees of freedom of the background grid
//--------------------------------------------------------------------------
// [AMPLE] sec 4 and sec 5.3: the degrees of freedom of the nodes that carry
// stiffness, less those with a Dirichlet condition. detFDoFs takes the nodes
// linked to a point (nIN); [AMPLE] takes the nodes of the active cells (eInA),
// activeCellDoFs: for GIMP/MPM the same set, while a CPDI point does not link a
// node whose basis value and gradient are zero there (elemMPinfo).
// Inputs:  mesh (bc, nodes; etpl, eInA) · mpData (nIN, nn)
// Outputs: fd (ascending list of free degrees of freedom)
// Tests:   tests/test_detFDoFs.cpp
//--------------------------------------------------------------------------
#pragma once
#include "mpData.h"

namespace ample {

std::vector<int> detFDoFs(const Mesh& mesh, const std::vector<MaterialPoint>& mpData);
std::vector<int> activeCellDoFs(const Mesh& mesh);  // [AMPLE]'s rule: nodes of active cells

}  // namespace ample
