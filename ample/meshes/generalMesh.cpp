//--------------------------------------------------------------------------
// generalMesh — a background mesh of triangles or quadrilaterals from a setup
//--------------------------------------------------------------------------
// See generalMesh.h for the checks, inputs and outputs.
//--------------------------------------------------------------------------
#include "generalMesh.h"
#include "cellSearch.h"
#include "ample/errors.h"
#include <sstream>

namespace ample {

namespace {
// the cell's nodes and coordinates, for messages
std::string describe(const Eigen::MatrixX2d& coord, const Eigen::MatrixXi& etpl, int e) {
  std::ostringstream s;
  s << "cell " << e << " (nodes";
  for (int a = 0; a < etpl.cols(); ++a)
    s << " " << etpl(e, a) << " at (" << coord(etpl(e, a), 0) << ", " << coord(etpl(e, a), 1) << ")";
  s << ")";
  return s.str();
}

// smallest turn (x_{a+1} - x_a) x (x_{a+2} - x_{a+1}) over the corners, and the largest,
// each divided by s^2
void turns(const Eigen::MatrixX2d& coord, const Eigen::MatrixXi& etpl, int e, double& tmin, double& tmax) {
  const int n = int(etpl.cols());
  Vector2d lo = coord.row(etpl(e, 0)).transpose(), hi = lo;
  for (int a = 1; a < n; ++a) {
    lo = lo.cwiseMin(coord.row(etpl(e, a)).transpose());
    hi = hi.cwiseMax(coord.row(etpl(e, a)).transpose());
  }
  const double s2 = (hi - lo).maxCoeff() * (hi - lo).maxCoeff();
  tmin = 1e300, tmax = -1e300;
  for (int a = 0; a < n; ++a) {
    const Vector2d p = coord.row(etpl(e, a)).transpose(), q = coord.row(etpl(e, (a + 1) % n)).transpose(),
                   r = coord.row(etpl(e, (a + 2) % n)).transpose();
    const Vector2d d1 = q - p, d2 = r - q;
    const double t = (d1(0) * d2(1) - d1(1) * d2(0)) / s2;
    tmin = std::min(tmin, t), tmax = std::max(tmax, t);
  }
  if (!(s2 > 0)) tmin = tmax = 0;
}
}  // namespace

Mesh generalMesh(const Eigen::MatrixX2d& coord, const Eigen::MatrixXi& etpl) {
  const int n = int(etpl.cols());
  if (n != 3 && n != 4)
    throw InputError("generalMesh: etpl has " + std::to_string(n) + " columns; allowed 3 (linear "
                     "triangles) or 4 (bilinear quadrilaterals)");
  if (etpl.rows() == 0 || coord.rows() == 0) throw InputError("generalMesh: the mesh has no cells or no nodes");
  if (!coord.allFinite()) throw InputError("generalMesh: a nodal coordinate is not finite");
  for (int e = 0; e < etpl.rows(); ++e)
    for (int a = 0; a < n; ++a)
      if (etpl(e, a) < 0 || etpl(e, a) >= coord.rows())
        throw InputError("generalMesh: cell " + std::to_string(e) + " names node " +
                         std::to_string(etpl(e, a)) + "; allowed [0, " + std::to_string(coord.rows() - 1) + "]");
  for (int e = 0; e < etpl.rows(); ++e) {
    double tmin, tmax;
    turns(coord, etpl, e, tmin, tmax);
    if (tmin > 1e-12) continue;
    const std::string what = (tmax < -1e-12) ? "is listed clockwise: list its nodes anticlockwise"
                             : (n == 3)      ? "is degenerate (zero area)"
                                             : "is not convex or is degenerate (a bilinear cell needs "
                                               "a positive turn at every corner)";
    throw InputError("generalMesh: " + describe(coord, etpl, e) + " " + what);
  }
  Mesh mesh;
  mesh.type = (n == 3) ? MeshType::Tri3 : MeshType::Quad4;
  mesh.coord = coord;
  mesh.etpl = etpl;
  mesh.eInA.assign(etpl.rows(), 0);
  buildCellSearch(mesh);
  return mesh;
}

}  // namespace ample
