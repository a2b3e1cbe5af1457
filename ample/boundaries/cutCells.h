//--------------------------------------------------------------------------
// cutCells — the grid cells each segment of an implicit boundary crosses
//--------------------------------------------------------------------------
// [Boundaries] sec 4, fig 4(f) and fig 5: only the cells cut by a boundary get the
// stiffness terms K2, K3 (eqs 26-27), integrated along the piece of the segment
// inside the cell. Segment s runs x(r) = x_s + r (x_s+1 - x_s), r in [0, 1]; it
// is split where it crosses a grid line, and each piece of positive length
// gives one CutCell with its parameter range [r0, r1]. Pieces are listed
// segment by segment, r increasing. A piece that lies on a grid line belongs
// to the cell on the solid side (where its band of width delta lies); a piece
// that only touches a cell at a node gives nothing; pieces outside the grid
// are left out.
// Inputs:  mesh (nelsx, nelsy, origin, h) · b (boundary)
// Outputs: the cut cells (segment, cell, r0, r1), in that order
// The grid lines are those of the regular grid: a general mesh gets an InputError.
// Tests:   tests/test_boundary.cpp, tests/test_mesh.cpp (refusal)
//--------------------------------------------------------------------------
#pragma once
#include "boundary.h"
#include "ample/mpData.h"
#include <vector>

namespace ample {

struct CutCell {
  int seg;        // segment of the boundary
  int cell;       // grid cell (0-based, row by row, x fastest)
  double r0, r1;  // parameter range of the segment inside the cell, 0 <= r0 < r1 <= 1
};

std::vector<CutCell> cutCells(const Mesh& mesh, const Boundary& b);

}  // namespace ample
