//--------------------------------------------------------------------------
// shapefunc — bi-linear finite element shape functions of a quadrilateral
//--------------------------------------------------------------------------
// [AMPLE] table 1. N_a = (1 + xi xi_a)(1 + eta eta_a)/4 for the corner nodes
// (-1,-1), (1,-1), (1,1), (-1,1) (the order of formCoord2D's cells).
// Inputs:  xsi (2) local coordinates
// Outputs: N (4) shape functions
// Tests:   tests/test_grid.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"

namespace ample {

Eigen::Vector4d shapefunc(const Vector2d& xsi);

}  // namespace ample
