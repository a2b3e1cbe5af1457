//--------------------------------------------------------------------------
// loneNodes — detFDoFs less the redundant dofs of lone nodes
//--------------------------------------------------------------------------
// See loneNodes.h for the rules, inputs and outputs.
//--------------------------------------------------------------------------
#include "loneNodes.h"
#include "ample/cpdi/cornerBasis.h"
#include "ample/cpdi/domainCorners.h"
#include <algorithm>
#include <array>
#include <cmath>

namespace ample {

// the only domain corner at which the basis of the point's node v is non-zero,
// or -1 (none, or more than one); S = cornerBasis at the corners
static int singleCorner(const CornerBasis& S, int v) {
  int only = -1;
  for (int c = 0; c < 4; ++c)
    if (S(v, c) != 0.0) {
      if (only >= 0) return -1;
      only = c;
    }
  return only;
}

// a GIMP or MPM point's lone nodes (linked to no other point): per direction i, keep
// free only the dofs whose basis vectors a_v = (S_v, dS_v/dx, dS_v/dy) (each row
// scaled by its largest magnitude over the point's nodes) are independent, taken
// in order of decreasing |S_v|; a vector within 1e-10 |a_v| of the span of the
// kept ones is a combination of them and its dof is left out (at most 3 kept)
static void keepIndependentLoneNodes(const MaterialPoint& mp, const std::vector<int>& links,
                                     std::vector<char>& isFree) {
  Eigen::Vector3d scale = Eigen::Vector3d::Zero();
  for (int v = 0; v < mp.nn; ++v)
    scale = scale.cwiseMax(Eigen::Vector3d(mp.Svp[v], mp.dSvp(0, v), mp.dSvp(1, v)).cwiseAbs());
  std::array<int, MAXN> order;
  int lone = 0;
  for (int v = 0; v < mp.nn; ++v)
    if (links[mp.nIN[v]] == 1) order[lone++] = v;
  if (lone < 2 || (scale.array() == 0.0).any()) return;  // no redundancy, or no basis yet
  std::stable_sort(order.begin(), order.begin() + lone,
                   [&](int a, int b) { return std::abs(mp.Svp[a]) > std::abs(mp.Svp[b]); });
  for (int i = 0; i < nD; ++i) {
    Eigen::Matrix3d q;                      // orthonormal basis of the kept vectors
    int kept = 0;
    for (int k = 0; k < lone; ++k) {
      const int v = order[k], d = dof(mp.nIN[v], i);
      if (!isFree[d]) continue;
      const Eigen::Vector3d a =
          Eigen::Vector3d(mp.Svp[v], mp.dSvp(0, v), mp.dSvp(1, v)).cwiseQuotient(scale);
      Eigen::Vector3d r = a;
      for (int j = 0; j < kept; ++j) r -= q.col(j).dot(r) * q.col(j);
      if (kept < 3 && r.norm() > 1e-10 * a.norm()) {
        q.col(kept++) = r.normalized();
      } else {
        isFree[d] = 0;                      // a combination of the kept dofs' vectors
      }
    }
  }
}

// the number of points linked to each node (node n: count[n])
static std::vector<int> pointsPerNode(int nodes, const std::vector<MaterialPoint>& mpData) {
  std::vector<int> count(nodes, 0);
  for (const MaterialPoint& mp : mpData)
    std::for_each(mp.nIN.begin(), mp.nIN.begin() + mp.nn, [&count](int node) { ++count[node]; });
  return count;
}

std::vector<int> detFDoFsLone(const Mesh& mesh, const std::vector<MaterialPoint>& mpData,
                              const StiffnessSources& others) {
  std::vector<int> links = pointsPerNode(mesh.nodes(), mpData);
  std::vector<char> isFree(mesh.nDoF(), 0); // 1: the dof is solved for
  for (int d : detFDoFs(mesh, mpData)) isFree[d] = 1;
  for (const SpMat* K : others)             // a node stiffened otherwise is not lone
    if (K && K->cols() == mesh.nDoF())
      for (int d = 0; d < K->cols(); ++d)
        if (K->col(d).nonZeros() > 0) links[d / nD] += 2;
  for (const MaterialPoint& mp : mpData)    // GIMP/MPM: a point's redundant lone nodes
    if (!isCPDI(mp)) keepIndependentLoneNodes(mp, links, isFree);

  for (const MaterialPoint& mp : mpData) {  // nodes only one CPDI corner reaches
    if (!isCPDI(mp)) continue;
    bool lone = false;                      // a node that only this point reaches?
    for (int v = 0; v < mp.nn; ++v) lone = lone || links[mp.nIN[v]] == 1;
    if (!lone) continue;
    const CornerBasis S = cornerBasis(mesh, mp, domainCorners(mp));
    int keep[4][nD];                        // per corner and direction: the free dof kept
    for (auto& k : keep) k[0] = k[1] = -1;
    for (int v = 0; v < mp.nn; ++v) {
      const int n = mp.nIN[v];
      if (links[n] != 1) continue;
      const int c = singleCorner(S, v);
      if (c < 0) continue;
      for (int i = 0; i < nD; ++i) {
        const int d = dof(n, i);
        if (!isFree[d]) continue;
        int& k = keep[c][i];
        if (k < 0) { k = v; continue; }
        if (std::abs(mp.Svp[v]) > std::abs(mp.Svp[k])) {  // keep the largest basis value
          isFree[dof(mp.nIN[k], i)] = 0;
          k = v;
        } else {
          isFree[d] = 0;
        }
      }
    }
  }
  std::vector<int> fd;
  for (int d = 0; d < mesh.nDoF(); ++d)
    if (isFree[d]) fd.push_back(d);
  return fd;
}

}  // namespace ample
