//--------------------------------------------------------------------------
// cellBasis — basis values and gradients of one cell of a general mesh at x
//--------------------------------------------------------------------------
// See cellBasis.h for the equations, inputs and outputs.
//--------------------------------------------------------------------------
#include "cellBasis.h"
#include "ample/errors.h"
#include <cmath>
#include <sstream>

namespace ample {

namespace {
using Corners4 = Eigen::Matrix<double, nD, nen>;
constexpr double snap = 1e-14;  // the Newton tolerance: closer than this to an edge is on it
constexpr double roundOffFloor = 1e-12;  // accepted after 30 passes (round-off of a distorted cell)

// a local coordinate within snap of the edge value `at` is put on it, so that the basis
// functions of the nodes off that edge are exactly zero there (as SvpMPM's on the grid)
double onEdge(double v, double at) { return std::abs(v - at) <= snap ? at : v; }

CellBasis triangleBasis(const Corners4& X, const Vector2d& x) {  // X: corners about node 0
  // BEGIN EXERCISE cellBasis
  const Vector2d a = X.col(1), b = X.col(2);
  const double A2 = a(0) * b(1) - a(1) * b(0);
  CellBasis c;
  c.N[1] = (x(0) * b(1) - x(1) * b(0)) / A2;
  c.N[2] = onEdge((a(0) * x(1) - a(1) * x(0)) / A2, 0.0);
  c.N[1] = onEdge(c.N[1], 0.0);
  if (std::abs(1.0 - c.N[1] - c.N[2]) <= snap) c.N[2] = 1.0 - c.N[1];  // then N0 = 0 exactly
  c.N[0] = 1.0 - c.N[1] - c.N[2];
  for (int i = 0; i < 3; ++i) {
    const Vector2d& j = X.col((i + 1) % 3);
    const Vector2d& k = X.col((i + 2) % 3);
    c.dN.col(i) = Vector2d(j(1) - k(1), k(0) - j(0)) / A2;
  }
  c.xi = Vector2d(c.N[1], c.N[2]);
  return c;
  // END EXERCISE
}

// dN_a/dxi (row 0) and dN_a/deta (row 1), and N_a, at xi
void quadShape(const Vector2d& xi, Eigen::Matrix<double, 1, nen>& N, Corners4& dNdxi) {
  const double xa[nen] = {-1, 1, 1, -1}, ea[nen] = {-1, -1, 1, 1};
  for (int a = 0; a < nen; ++a) {
    N(a) = 0.25 * (1 + xa[a] * xi(0)) * (1 + ea[a] * xi(1));
    dNdxi(0, a) = 0.25 * xa[a] * (1 + ea[a] * xi(1));
    dNdxi(1, a) = 0.25 * ea[a] * (1 + xa[a] * xi(0));
  }
}

[[noreturn]] void newtonFailed(int e, const Vector2d& x, double step, const char* why) {
  std::ostringstream msg;
  msg << "local coordinates of (" << x(0) << ", " << x(1) << ") in quadrilateral " << e << ": "
      << why << " (last |dxi| = " << step << ")";
  throw RunError(msg.str());
}

// the basis at the converged local coordinates (put on an edge within snap)
CellBasis quadAt(const Corners4& X, CellBasis c, int passes) {
  Eigen::Matrix<double, 1, nen> N;
  Corners4 dNdxi;
  c.passes = passes;
  for (int i = 0; i < nD; ++i) c.xi(i) = onEdge(onEdge(c.xi(i), -1.0), 1.0);
  quadShape(c.xi, N, dNdxi);
  const Eigen::Matrix2d J = X * dNdxi.transpose();
  for (int a = 0; a < nen; ++a) c.N[a] = N(a);
  c.dN = J.inverse().transpose() * dNdxi;   // grad N = J^-T dN/dxi
  return c;
}

CellBasis quadBasis(const Corners4& X, const Vector2d& x, int e, const Vector2d& xGlobal) {
  CellBasis c;
  Eigen::Matrix<double, 1, nen> N;
  Corners4 dNdxi;
  double step = 0;
  for (int it = 1; it <= 30; ++it) {
    quadShape(c.xi, N, dNdxi);
    const Eigen::Matrix2d J = X * dNdxi.transpose();  // J(i, j) = dx_i / dxi_j
    if (!(J.determinant() > 0)) newtonFailed(e, xGlobal, step, "det J <= 0 (point far outside the cell)");
    const Vector2d dxi = J.inverse() * (X * N.transpose() - x);
    c.xi -= dxi;
    step = dxi.cwiseAbs().maxCoeff();
    if (step <= snap) return quadAt(X, c, it);
  }
  // a strongly distorted cell (FE mode) can hold |dxi| at its round-off, just above snap
  if (step <= roundOffFloor) return quadAt(X, c, 30);
  newtonFailed(e, xGlobal, step, "Newton did not converge to 1e-14 (nor to 1e-12) in 30 passes");
}
}  // namespace

CellBasis cellBasis(const Mesh& mesh, int e, const Vector2d& x) {
  const int n = mesh.cellNodes();
  const Vector2d x0 = mesh.coord.row(mesh.etpl(e, 0)).transpose();
  Corners4 X = Corners4::Zero();                  // corners about node 0
  for (int a = 0; a < n; ++a) X.col(a) = mesh.coord.row(mesh.etpl(e, a)).transpose() - x0;
  return (n == 3) ? triangleBasis(X, x - x0) : quadBasis(X, x - x0, e, x);
}

int localNode(const Mesh& mesh, int e, int node) {
  for (int a = 0; a < mesh.cellNodes(); ++a)
    if (mesh.etpl(e, a) == node) return a;
  return -1;
}

}  // namespace ample
