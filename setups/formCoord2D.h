//--------------------------------------------------------------------------
// formCoord2D — regular background grid of bi-linear quadrilaterals
//--------------------------------------------------------------------------
// [AMPLE] table 1. Nodes are numbered row by row (x fastest), cells too;
// cell nodes run anticlockwise from the lower-left corner.
// Inputs:  nelsx, nelsy (cells in x and y) · lx, ly (grid size, m)
// Outputs: mesh.etpl (nels x 4) · mesh.coord (nodes x 2) · mesh.h · nelsx, nelsy
//          (bc and eInA are left empty for the setup to fill)
// Tests:   tests/test_grid.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"

namespace ample {

Mesh formCoord2D(int nelsx, int nelsy, double lx, double ly);

}  // namespace ample
