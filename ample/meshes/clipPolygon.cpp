//--------------------------------------------------------------------------
// clipPolygon — the part of a polygon inside a convex window (Sutherland-Hodgman)
//--------------------------------------------------------------------------
// See clipPolygon.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "clipPolygon.h"

namespace ample {

namespace {
double cross(const Vector2d& u, const Vector2d& v) { return u(0) * v(1) - u(1) * v(0); }
}  // namespace

Polygon clipPolygon(const Polygon& subject, const Polygon& window) {
  Polygon out = subject;
  for (size_t w = 0; w < window.size() && !out.empty(); ++w) {  // one window edge a -> b
    const Vector2d a = window[w], ab = window[(w + 1) % window.size()] - a;
    const Polygon in = out;
    out.clear();
    for (size_t i = 0; i < in.size(); ++i) {  // subject edge p -> q
      const Vector2d& p = in[i];
      const Vector2d& q = in[(i + 1) % in.size()];
      const double sp = cross(ab, p - a), sq = cross(ab, q - a);  // >= 0: inside (left)
      if (sp >= 0) out.push_back(p);
      if ((sp >= 0) != (sq >= 0)) out.push_back(p + sp / (sp - sq) * (q - p));  // crossing
    }
  }
  return out;
}

AreaCentroid polygonArea(const Polygon& poly) {
  AreaCentroid ac;
  Vector2d moment = Vector2d::Zero();  // 6 x first moment
  for (size_t i = 0; i < poly.size(); ++i) {
    const Vector2d& p = poly[i];
    const Vector2d& q = poly[(i + 1) % poly.size()];
    const double c = cross(p, q);
    ac.area += 0.5 * c;
    moment += c * (p + q);
  }
  if (ac.area != 0.0) ac.centroid = moment / (6.0 * ac.area);
  return ac;
}

}  // namespace ample
