//--------------------------------------------------------------------------
// cellSearch — the cell of a general background mesh that holds a point
//--------------------------------------------------------------------------
// See cellSearch.h for the rule, inputs and outputs.
//--------------------------------------------------------------------------
#include "cellSearch.h"
#include "ample/errors.h"
#include <algorithm>
#include <cmath>
#include <sstream>

namespace ample {

namespace {
constexpr double tol = 1e-9;  // in edge lengths (elemForMP: 1e-9 h)

Vector2d node(const Mesh& mesh, int e, int a) { return mesh.coord.row(mesh.etpl(e, a)).transpose(); }

// bounding box of cell e, widened by tol of its size
void cellBox(const Mesh& mesh, int e, Vector2d& lo, Vector2d& hi) {
  lo = hi = node(mesh, e, 0);
  for (int a = 1; a < mesh.cellNodes(); ++a) {
    lo = lo.cwiseMin(node(mesh, e, a));
    hi = hi.cwiseMax(node(mesh, e, a));
  }
  const double pad = tol * (hi - lo).maxCoeff();
  lo.array() -= pad;
  hi.array() += pad;
}

// bucket index range [i0, i1] in direction k of the interval [a, b]
void bucketRange(const CellSearch& s, int k, double a, double b, int& i0, int& i1) {
  const int n = (k == 0) ? s.nbx : s.nby;
  i0 = std::clamp(int(std::floor((a - s.lo(k)) / s.size(k))), 0, n - 1);
  i1 = std::clamp(int(std::floor((b - s.lo(k)) / s.size(k))), 0, n - 1);
}
}  // namespace

void buildCellSearch(Mesh& mesh) {
  CellSearch& s = mesh.search;
  const int nels = mesh.nels();
  Vector2d lo = mesh.coord.colwise().minCoeff().transpose(), hi = mesh.coord.colwise().maxCoeff().transpose();
  const Vector2d w = (hi - lo).cwiseMax(1e-300);
  s.nbx = std::clamp(int(std::ceil(std::sqrt(nels * w(0) / w(1)))), 1, 4096);  // ~ one cell a bucket
  s.nby = std::clamp(int(std::ceil(double(nels) / s.nbx)), 1, 4096);
  s.lo = lo;
  s.size = w.cwiseQuotient(Vector2d(s.nbx, s.nby));
  std::vector<int> count(size_t(s.nbx) * s.nby + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {                 // count, then fill (cells ascending)
    if (pass == 1) {
      s.start.assign(count.size(), 0);
      for (size_t b = 0; b + 1 < count.size(); ++b) s.start[b + 1] = s.start[b] + count[b];
      s.cells.assign(s.start.back(), 0);
      std::fill(count.begin(), count.end(), 0);
    }
    for (int e = 0; e < nels; ++e) {
      Vector2d a, b;
      cellBox(mesh, e, a, b);
      int i0, i1, j0, j1;
      bucketRange(s, 0, a(0), b(0), i0, i1);
      bucketRange(s, 1, a(1), b(1), j0, j1);
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
          const int k = j * s.nbx + i;
          if (pass == 1) s.cells[s.start[k] + count[k]] = e;
          count[k]++;
        }
    }
  }
}

bool insideCell(const Mesh& mesh, int e, const Vector2d& x) {
  const int n = mesh.cellNodes();
  for (int a = 0; a < n; ++a) {
    const Vector2d p = node(mesh, e, a), q = node(mesh, e, (a + 1) % n), d = q - p, r = x - p;
    if (d(0) * r(1) - d(1) * r(0) < -tol * d.squaredNorm()) return false;
  }
  return true;
}

int findCell(const Mesh& mesh, const Vector2d& x) {
  const CellSearch& s = mesh.search;
  const Vector2d hiBox = s.lo + s.size.cwiseProduct(Vector2d(s.nbx, s.nby));
  const Vector2d pad = 1e-9 * (hiBox - s.lo);
  if ((x - (s.lo - pad)).minCoeff() < 0 || ((hiBox + pad) - x).minCoeff() < 0) return -1;
  int i, j, unused;
  bucketRange(s, 0, x(0), x(0), i, unused);
  bucketRange(s, 1, x(1), x(1), j, unused);
  const int k = j * s.nbx + i;
  for (int c = s.start[k]; c < s.start[k + 1]; ++c)
    if (insideCell(mesh, s.cells[c], x)) return s.cells[c];
  return -1;
}

const char* meshName(const Mesh& mesh) {
  switch (mesh.type) {
    case MeshType::Grid: return "regular grid";
    case MeshType::Tri3: return "triangle mesh";
    case MeshType::Quad4: return "quadrilateral mesh";
  }
  return "mesh";
}

int cellOf(const Mesh& mesh, const Vector2d& x) {
  const int e = findCell(mesh, x);
  if (e >= 0) return e;
  const Vector2d lo = mesh.search.lo, hi = lo + mesh.search.size.cwiseProduct(Vector2d(mesh.search.nbx, mesh.search.nby));
  std::ostringstream msg;
  msg << "material point at (" << x(0) << ", " << x(1) << ") has left the background "
      << meshName(mesh) << " (" << mesh.nels() << " cells in the box [" << lo(0) << ", " << hi(0)
      << "] x [" << lo(1) << ", " << hi(1) << "]): it lies in none of its cells";
  throw RunError(msg.str(), Failure::LeftGrid);
}

// a CPDI domain corner: the cell that holds the corner moved 1e-6 of the way towards the
// point (a corner on an edge goes to the domain's side); a corner outside every cell takes
// the last cell along the line from the point to it (bisection, 40 halvings)
int cornerCell(const Mesh& mesh, const Vector2d& corner, const Vector2d& mpC) {
  const int e = findCell(mesh, corner + 1e-6 * (mpC - corner));
  if (e >= 0) return e;
  double in = 0.0, out = 1.0;  // mpC + t (corner - mpC): inside at t = in, outside at t = out
  for (int k = 0; k < 40; ++k) {
    const double t = 0.5 * (in + out);
    (findCell(mesh, mpC + t * (corner - mpC)) >= 0 ? in : out) = t;
  }
  return cellOf(mesh, mpC + in * (corner - mpC));  // throws if the point itself is outside
}

}  // namespace ample
