//--------------------------------------------------------------------------
// cellSearch — the cell of a general background mesh that holds a point
//--------------------------------------------------------------------------
// docs/meshes.md. The regular grid finds its cells from the spacing
// (elemForMP); a general mesh of triangles or convex quadrilaterals uses a
// bucket grid over its bounding box, built once per mesh (buildCellSearch:
// about one cell per bucket; bucket (i, j) lists, ascending, every cell whose
// bounding box, widened by 1e-9 of its size, overlaps the bucket). findCell
// takes the bucket of x and returns the first (lowest-numbered) of its cells
// for which x lies on the inner side of every edge a -> b (anticlockwise):
//   (b - a) x (x - a) >= -tol |b - a|^2,   tol = 1e-9,
// i.e. x is inside or within 1e-9 edge lengths of the cell. So a point on a
// shared edge or vertex goes to the lowest-numbered cell that holds it; on a
// regular grid numbered row by row this is the cell to the left / below, as
// elemForMP's rule for standard MPM.
// cornerCell: the cell of a CPDI domain corner: the cell that holds the corner
// moved 1e-6 of the way towards its point (on an edge: the domain's side); a
// corner outside the mesh (a domain that sticks out past a curved boundary or
// into a hole) takes the last cell along the line from the point to the corner
// (found by bisection), whose basis cellBasis continues beyond its edge.
// Inputs:  mesh (type, coord, etpl; search for findCell) · x (2)
// Outputs: mesh.search (buildCellSearch) · cell number, or -1 outside every
//          cell (findCell) · cellOf: the cell, or RunError naming the point ·
//          cornerCell: a cell (RunError if the point is outside)
// Tests:   tests/test_mesh.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"

namespace ample {

void buildCellSearch(Mesh& mesh);
bool insideCell(const Mesh& mesh, int e, const Vector2d& x);  // the edge test above
int findCell(const Mesh& mesh, const Vector2d& x);            // -1: outside every cell
int cellOf(const Mesh& mesh, const Vector2d& x);              // throws RunError outside
int cornerCell(const Mesh& mesh, const Vector2d& corner, const Vector2d& mpC);  // below
const char* meshName(const Mesh& mesh);  // "regular grid", "triangle mesh", "quadrilateral mesh"

}  // namespace ample
