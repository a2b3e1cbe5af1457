//--------------------------------------------------------------------------
// boundary.h — an implicit boundary: a polyline with a condition per segment
//--------------------------------------------------------------------------
// [Boundaries] secs 2.4-3.2. A boundary that need not follow the grid lines: straight
// segments between the points x_0, x_1, ..., each with its condition. The solid
// lies on one side of the polyline (default: on the left walking from x_0 to
// x_1, i.e. the polyline runs anticlockwise round the solid). phi, the signed
// distance of [Boundaries] eq 16, is positive in the solid; n is the inward unit
// normal (into the solid, the paper's n-axis of fig 3 and eq 25), t = n turned
// by +90 degrees, so that T = [n^T; t^T] is the rotation of eq 25.
// A setup's boundaries are held in its Analysis, opaque to the core (Analysis::
// boundaries, a std::any): boundariesOf(an) is the list, empty when there is none;
// editBoundaries(an) the same to change, made empty on first use (addBoundary).
// Functions: dirichletBand (eq 16), cutCells; setups/setupHelpers (addBoundary,
//            fillPolygon). Page: docs/implicitBoundaries.md
// Tests:   tests/test_boundary.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/analysis.h"
#include <algorithm>
#include <any>
#include <vector>

namespace ample {

enum class BoundaryType {
  Fixed,            // u = 0 (both directions)
  Roller,           // u.n = 0, the tangent t free (zero shear traction)
  Prescribed,       // u = du per load step (both directions; a rough footing)
  PrescribedNormal  // u.n = du.n per load step, t free (the pushed side of [Boundaries] sec 5.1)
};
enum class SolidSide { Left, Right };  // where the solid lies, walking from x_0 to x_1
// the inner integral of K2 over the d entries of [D1bar] (eqs 21, 26): Consistent = 1 (the
// default), the variationally consistent (Nitsche) coupling, exact for a linear field, which
// the paper's own numbers need (table I at 0 degrees, fig 16); Paper = int d d' = 1/2 as the
// extraction prints eqs 21, 26 (docs/implicitBoundaries.md, "The factor 1/2")
enum class IbCoupling { Paper, Consistent };

struct Boundary {
  std::vector<Vector2d> x;            // end points of the segments (at least two)
  std::vector<BoundaryType> type;     // condition of segment s = [x_s, x_s+1] (x.size() - 1)
  SolidSide solid = SolidSide::Left;  // side of the solid
  double delta = 0;                   // band width delta of eq 16 (m); addBoundary: 1e-6 h
  std::vector<Vector2d> du;           // Prescribed*: displacement increment of load step lstp
                                      // in du[lstp - 1]; the last entry holds for later steps
  IbCoupling coupling = IbCoupling::Consistent;  // K2's int d d' (eqs 21, 26)
  std::vector<Vector2d> curveNormal;  // a curve's inward unit normal at each x_s (empty: the
                                      // segments' own); sec 4: n, t vary along the segment
  int segments() const { return int(x.size()) - 1; }
};

// inward unit normal n of segment s (into the solid)
inline Vector2d inwardNormal(const Boundary& b, int s) {
  const Vector2d d = (b.x[s + 1] - b.x[s]).normalized();
  return b.solid == SolidSide::Left ? Vector2d(-d(1), d(0)) : Vector2d(d(1), -d(0));
}
// tangent t of segment s: n turned by +90 degrees (the second row of T, eq 25)
inline Vector2d tangent(const Boundary& b, int s) {
  const Vector2d n = inwardNormal(b, s);
  return Vector2d(-n(1), n(0));
}
// phi of eq 16: signed distance of p from the line of segment s, positive in the solid
inline double signedDistance(const Boundary& b, int s, const Vector2d& p) {
  return (p - b.x[s]).dot(inwardNormal(b, s));
}
// normal used by K2, K3 at the parameter r of segment s: the segment's own, or for a curve
// (curveNormal given) the normalised interpolation of the curve's normals at its ends
inline Vector2d stiffnessNormal(const Boundary& b, int s, double r) {
  if (b.curveNormal.empty()) return inwardNormal(b, s);
  return ((1 - r) * b.curveNormal[s] + r * b.curveNormal[s + 1]).normalized();
}
// point of segment s at the parameter r in [0, 1]: x_s + r (x_s+1 - x_s)
inline Vector2d pointAt(const Boundary& b, int s, double r) {
  return b.x[s] + r * (b.x[s + 1] - b.x[s]);
}
// the implicit boundaries of an analysis (Analysis::boundaries)
inline const std::vector<Boundary>& boundariesOf(const Analysis& an) {
  static const std::vector<Boundary> none;
  const auto* list = std::any_cast<std::vector<Boundary>>(&an.boundaries);
  return list ? *list : none;
}
inline std::vector<Boundary>& editBoundaries(Analysis& an) {  // made empty on first use
  if (!an.boundaries.has_value()) an.boundaries = std::vector<Boundary>();
  return std::any_cast<std::vector<Boundary>&>(an.boundaries);
}
// prescribed displacement increment of load step lstp (1-based); zero if none given
inline Vector2d duAt(const Boundary& b, int lstp) {
  if (b.du.empty()) return Vector2d::Zero();
  return b.du[std::min(size_t(std::max(lstp, 1)), b.du.size()) - 1];
}

}  // namespace ample
