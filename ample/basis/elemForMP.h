//--------------------------------------------------------------------------
// elemForMP — background grid cells overlapped by a material point's domain
//--------------------------------------------------------------------------
// [AMPLE] table 1. A cell belongs to the point when it overlaps the domain
// [x_p - l_p, x_p + l_p] in every direction with positive length (a cell that
// only touches the domain edge carries zero basis functions and is left out;
// "touching" allows a round-off of 1e-9 h). A standard MPM point (l_p = 0)
// belongs to the cell X_k < x <= X_k+1 in each direction (on a cell edge: the
// cell to the left/below), the same intervals as SvpMPM (eq 23).
// The grid is regular, so the cells follow from the spacing without a search.
// A domain reaching past the grid edge uses the cells inside the grid only.
// (A general mesh: meshElemForMP, ample/meshes/elemMPinfoMesh.h.)
// Inputs:  mesh (nelsx, nelsy, h, origin) · mpC (2) · lp (2)
// Outputs: eIN (cells, ascending) · ne (their number); throws RunError if the
//          point itself is outside the grid or its domain overlaps more than
//          3 x 3 cells
// Tests:   tests/test_grid.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"

namespace ample {

int elemForMP(const Mesh& mesh, const Vector2d& mpC, const Vector2d& lp,
              std::array<int, MAXE>& eIN);

}  // namespace ample
