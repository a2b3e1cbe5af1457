//--------------------------------------------------------------------------
// cutCells — the grid cells each segment of an implicit boundary crosses
//--------------------------------------------------------------------------
// See cutCells.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "cutCells.h"
#include "ample/errors.h"
#include <algorithm>
#include <cmath>

namespace ample {

namespace {
constexpr double onLine = 1e-9;  // |q - round(q)| below this (in cells): on a grid line
constexpr double tiny = 1e-12;   // lengths below tiny h count as zero

// parameters r in (0, 1) where the segment a -> c crosses the grid lines of axis k
void crossings(const Mesh& mesh, const Vector2d& a, const Vector2d& c, int k,
               std::vector<double>& r) {
  const double d = c(k) - a(k), h = mesh.h(k), o = mesh.origin(k);
  if (std::abs(d) <= tiny * h) return;  // parallel to these grid lines
  const double q0 = (std::min(a(k), c(k)) - o) / h, q1 = (std::max(a(k), c(k)) - o) / h;
  for (double i = std::ceil(q0); i <= q1; ++i) {
    const double t = (o + i * h - a(k)) / d;
    if (t > 0.0 && t < 1.0) r.push_back(t);
  }
}
}  // namespace

std::vector<CutCell> cutCells(const Mesh& mesh, const Boundary& b) {
  if (!mesh.regular())
    throw InputError("implicit boundaries ([Boundaries]) need the regular grid: cutCells walks its grid lines");
  std::vector<CutCell> cut;
  for (int s = 0; s < b.segments(); ++s) {
    const Vector2d a = b.x[s], c = b.x[s + 1], n = inwardNormal(b, s);
    const double L = (c - a).norm();
    std::vector<double> r = {0.0, 1.0};
    for (int k = 0; k < nD; ++k) crossings(mesh, a, c, k, r);
    std::sort(r.begin(), r.end());
    for (size_t i = 0; i + 1 < r.size(); ++i) {
      if ((r[i + 1] - r[i]) * L <= tiny * mesh.h.minCoeff()) continue;  // at a node: no piece
      const Vector2d m = pointAt(b, s, 0.5 * (r[i] + r[i + 1]));      // midpoint of the piece
      int e[nD];
      for (int k = 0; k < nD; ++k) {
        const double q = (m(k) - mesh.origin(k)) / mesh.h(k);
        const bool parallel = std::abs(c(k) - a(k)) <= tiny * mesh.h(k);
        if (parallel && std::abs(q - std::round(q)) < onLine)  // on a grid line:
          e[k] = int(std::round(q)) - (n(k) > 0 ? 0 : 1);      // the cell on the solid side
        else
          e[k] = int(std::floor(q));
      }
      if (e[0] < 0 || e[0] >= mesh.nelsx || e[1] < 0 || e[1] >= mesh.nelsy) continue;
      cut.push_back({s, e[1] * mesh.nelsx + e[0], r[i], r[i + 1]});
    }
  }
  return cut;
}

}  // namespace ample
