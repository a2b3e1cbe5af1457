//--------------------------------------------------------------------------
// detMpPos — local positions of mp x mp equally spaced points in a cell
//--------------------------------------------------------------------------
// [AMPLE] table 1. Local coordinates in [-1, 1]: (2i+1)/mp - 1, i = 0..mp-1;
// the point order runs over xi first (outer) and eta second (inner).
// Inputs:  mp (points per direction, >= 1)
// Outputs: mpPos (mp^2 x 2) local coordinates
// Tests:   tests/test_grid.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"

namespace ample {

Eigen::MatrixX2d detMpPos(int mp);

}  // namespace ample
