//--------------------------------------------------------------------------
// generalMesh — a background mesh of triangles or quadrilaterals from a setup
//--------------------------------------------------------------------------
// docs/meshes.md. The setup gives the nodal coordinates and the cells' nodes
// (3 per linear triangle, 4 per bilinear quadrilateral, anticlockwise); the
// cells are checked and the bucket grid of the point search is built
// (buildCellSearch). A triangle needs a signed area
//   A = (x1 - x0) x (x2 - x0) / 2 > 1e-12 s^2,
// a quadrilateral a positive turn at every corner,
//   (x_{a+1} - x_a) x (x_{a+2} - x_{a+1}) > 1e-12 s^2   (a = 0..3),
// i.e. convex and anticlockwise, so det J > 0 in the whole cell (s: the
// larger side of the cell's bounding box). nelsx, nelsy, h stay 0: the
// spacing-based code (GIMP, ghost penalty, implicit boundaries) refuses the mesh.
// Inputs:  coord (nodes x 2) · etpl (cells x 3 or 4, 0-based node numbers)
// Outputs: Mesh (type Tri3 or Quad4, coord, etpl, eInA, search);
//          InputError naming the cell and its nodes for a bad cell
// Tests:   tests/test_mesh.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"

namespace ample {

Mesh generalMesh(const Eigen::MatrixX2d& coord, const Eigen::MatrixXi& etpl);

}  // namespace ample
