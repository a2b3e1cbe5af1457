//--------------------------------------------------------------------------
// ghostPenalty — ghost stabilisation of the cells at the edge of the body
//--------------------------------------------------------------------------
// See ghostPenalty.h for the method, its sources, inputs and outputs.
//--------------------------------------------------------------------------
#include "ghostPenalty.h"
#include "ample/errors.h"
#include <cmath>

namespace ample {

namespace {
// d N_a / d x_dir of the bi-linear basis of cell e at x (a = local node, anticlockwise
// from the lower-left), from the cell's own local coordinates so that a point on
// the cell edge takes this cell's slope
double dN(const Mesh& mesh, int e, int a, int dir, const Vector2d& x) {
  const Vector2d xi = (x - mesh.coord.row(mesh.etpl(e, 0)).transpose()).cwiseQuotient(mesh.h);
  const double ca[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // local corner coordinates
  const int o = 1 - dir;
  const double other = ca[a][o] * xi(o) + (1 - ca[a][o]) * (1 - xi(o));
  return (2 * ca[a][dir] - 1) / mesh.h(dir) * other;
}

bool active(const Mesh& mesh, int i, int j) {
  return i >= 0 && j >= 0 && i < mesh.nelsx && j < mesh.nelsy && mesh.eInA[j * mesh.nelsx + i];
}

bool edgeCell(const Mesh& mesh, int i, int j) {
  return !active(mesh, i - 1, j) || !active(mesh, i + 1, j) || !active(mesh, i, j - 1) ||
         !active(mesh, i, j + 1);
}
}  // namespace

SpMat ghostPenalty(const Mesh& mesh, double gamma, double E) {
  if (!mesh.regular()) throw InputError("the ghost penalty needs the regular grid (its faces); use ghost=0");
  std::vector<Eigen::Triplet<double>> trip;
  const double gp = 1.0 / std::sqrt(3.0);                        // 2-point Gauss on [-1, 1]
  for (int j = 0; j < mesh.nelsy; ++j)
    for (int i = 0; i < mesh.nelsx; ++i)
      for (int dir = 0; dir < nD; ++dir) {                       // face to the right / above
        const int i2 = i + (dir == 0), j2 = j + (dir == 1);
        if (!active(mesh, i, j) || !active(mesh, i2, j2)) continue;
        if (!edgeCell(mesh, i, j) && !edgeCell(mesh, i2, j2)) continue;
        const int eL = j * mesh.nelsx + i, eR = j2 * mesh.nelsx + i2;
        const double h = mesh.h(dir), len = mesh.h(1 - dir);
        const Vector2d c = mesh.coord.row(mesh.etpl(eR, 0)).transpose();  // face start
        for (double q : {-gp, gp}) {
          Vector2d x = c;
          x(1 - dir) += 0.5 * len * (1.0 + q);                   // Gauss point on the face
          int nodes[8];
          double g[8];                                           // jump of dN/dn per node
          for (int a = 0; a < nen; ++a) {
            nodes[a] = mesh.etpl(eR, a), g[a] = dN(mesh, eR, a, dir, x);
            nodes[a + 4] = mesh.etpl(eL, a), g[a + 4] = -dN(mesh, eL, a, dir, x);
          }
          for (int a = 0; a < 8; ++a)
            for (int b = 0; b < 8; ++b)
              for (int k = 0; k < nD; ++k)
                trip.emplace_back(dof(nodes[a], k), dof(nodes[b], k),
                                  gamma * E * h * 0.5 * len * g[a] * g[b]);
        }
      }
  SpMat K(mesh.nDoF(), mesh.nDoF());
  K.setFromTriplets(trip.begin(), trip.end());
  return K;
}

void addGhostPenalty(const SpMat& Kgp, const Eigen::VectorXd& uvw, SpMat& Kt, Eigen::VectorXd& fint) {
  if (Kgp.nonZeros() == 0) return;  // remedy off
  Kt = Kt + Kgp;                    // the pattern grows by the faces' couplings once
  fint += Kgp * uvw;                // penalty on the increment
}

}  // namespace ample
