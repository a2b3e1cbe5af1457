//--------------------------------------------------------------------------
// MPMbasis — two-dimensional basis functions and gradients of one point
//--------------------------------------------------------------------------
// [AMPLE] eq 22. See MPMbasis.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "MPMbasis.h"
#include "SvpCPDI.h"
#include "SvpGIMP.h"
#include "SvpMPM.h"
#include "ample/meshes/cellBasis.h"
#include "ample/meshes/cellSearch.h"
#include "ample/errors.h"

namespace ample {

// ---- the regular grid ([AMPLE]) ----------------------------------------

// the bi-linear basis of a grid node, the product of SvpMPM in x and y
double gridBasis(const Mesh& mesh, int node, const Vector2d& x) {
  return SvpMPM(x(0) - mesh.coord(node, 0), mesh.h(0)).S * SvpMPM(x(1) - mesh.coord(node, 1), mesh.h(1)).S;
}

// the grid basis of each of the point's nodes at each domain corner
static CornerBasis gridCornerBasis(const Mesh& mesh, const MaterialPoint& mp, const Corners& x) {
  CornerBasis S = CornerBasis::Zero();
  for (int v = 0; v < mp.nn; ++v)
    for (int c = 0; c < 4; ++c) S(v, c) = gridBasis(mesh, mp.nIN[v], x.col(c));
  return S;
}

// CPDI1 / CPDI2 from the basis of each node at the four corners S(v, c)
static void cpdiBasis(MaterialPoint& mp, const Corners& x, const CornerBasis& S) {
  for (int v = 0; v < mp.nn; ++v) {
    const Eigen::Vector4d Sc = S.row(v).transpose();  // basis of node v at the four corners
    const Basis2D b = (mp.mpType == MpType::CPDI1) ? SvpCPDI1(Sc, mp.cpdi->st) : SvpCPDI2(Sc, x);
    mp.Svp[v] = b.S;
    mp.dSvp.col(v) = b.dS;
  }
}

void MPMbasis(const Mesh& mesh, MaterialPoint& mp) {
  if (isCPDI(mp)) {
    const Corners x = domainCorners(mp);
    return cpdiBasis(mp, x, gridCornerBasis(mesh, mp, x));
  }
  // BEGIN EXERCISE MPMbasis
  for (int v = 0; v < mp.nn; ++v) {
    Basis1D b[nD];
    for (int i = 0; i < nD; ++i) {
      const double d = mp.mpC(i) - mesh.coord(mp.nIN[v], i);
      b[i] = (mp.mpType == MpType::MPM) ? SvpMPM(d, mesh.h(i)) : SvpGIMP(d, mesh.h(i), mp.lp(i));
    }
    mp.Svp[v] = b[0].S * b[1].S;
    mp.dSvp(0, v) = b[0].dS * b[1].S;
    mp.dSvp(1, v) = b[0].S * b[1].dS;
  }
  // END EXERCISE
}

// ---- a general mesh (docs/meshes.md) -------------------------------------

// each corner's cell searched once (outside the mesh: cornerCell's cell, its basis
// continued to the corner), the value of each of the point's nodes there
static CornerBasis meshCornerBasis(const Mesh& mesh, const MaterialPoint& mp, const Corners& x) {
  CornerBasis S = CornerBasis::Zero();
  for (int c = 0; c < 4; ++c) {
    int e = findCell(mesh, x.col(c));
    if (e < 0) e = cornerCell(mesh, x.col(c), mp.mpC);
    const CellBasis b = cellBasis(mesh, e, x.col(c));
    for (int v = 0; v < mp.nn; ++v) {
      const int a = localNode(mesh, e, mp.nIN[v]);
      S(v, c) = a < 0 ? 0.0 : b.N[a];
    }
  }
  return S;
}

// standard MPM from the basis of the point's one cell (cellBasis), CPDI from the
// cell basis at the corners; GIMP needs the regular grid
void meshMPMbasis(const Mesh& mesh, MaterialPoint& mp) {
  if (isCPDI(mp)) {
    const Corners x = domainCorners(mp);
    return cpdiBasis(mp, x, meshCornerBasis(mesh, mp, x));
  }
  if (mp.mpType == MpType::GIMP)
    throw InputError(std::string("mpType=2 (GIMP) needs the regular grid; the background mesh is a ") +
                     meshName(mesh) + " (use mpType=1 MPM, 3 CPDI1 or 4 CPDI2)");
  const int e = mp.eIN[0];
  const CellBasis b = cellBasis(mesh, e, mp.mpC);
  for (int v = 0; v < mp.nn; ++v) {
    const int a = localNode(mesh, e, mp.nIN[v]);
    mp.Svp[v] = b.N[a];
    mp.dSvp.col(v) = b.dN.col(a);
  }
}

// ---- either (detFDoFs, updateDomain) --------------------------------------

CornerBasis cornerBasis(const Mesh& mesh, const MaterialPoint& mp, const Corners& x) {
  return mesh.regular() ? gridCornerBasis(mesh, mp, x) : meshCornerBasis(mesh, mp, x);
}

}  // namespace ample
