//--------------------------------------------------------------------------
// clipPolygon — the part of a polygon inside a convex window (Sutherland-Hodgman)
//--------------------------------------------------------------------------
// [Boundaries] sec 4, fig 4(c)-(e): a point's square domain is cut by the solid.
// The solid is the subject and the square the window, so the solid may be any
// simple polygon, convex or not (a funnel); the window must be convex. Each
// edge of the window (anticlockwise) keeps the half-plane on its left. Where
// the solid leaves the window and comes back, the result holds edges along
// the window's side walked there and back: they add nothing to the area or
// the first moment, so polygonArea below stays exact.
// polygonArea: signed area (shoelace formula; > 0 anticlockwise) and the
// centroid (the first moment over the area; inside the polygon when it is
// convex, e.g. a square cut by a convex solid).
// Inputs:  subject (any simple polygon, either orientation) · window (convex,
//          anticlockwise) · poly (vertices, not repeated at the end)
// Outputs: clipped polygon (empty if nothing is inside) · {area, centroid}
// Tests:   tests/test_boundary.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"
#include <vector>

namespace ample {

using Polygon = std::vector<Vector2d>;

Polygon clipPolygon(const Polygon& subject, const Polygon& window);

struct AreaCentroid {
  double area = 0;                    // signed area (> 0 anticlockwise)
  Vector2d centroid = Vector2d::Zero();  // (0, 0) for a polygon of zero area
};
AreaCentroid polygonArea(const Polygon& poly);

}  // namespace ample
