//--------------------------------------------------------------------------
// MPMbasis — two-dimensional basis functions and gradients of one point
//--------------------------------------------------------------------------
// Seed 002 eq 22. See MPMbasis.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "MPMbasis.h"
#include "SvpCPDI.h"
#include "SvpGIMP.h"
#include "SvpMPM.h"
#include "cellBasis.h"
#include "cellSearch.h"
#include "errors.h"

namespace ample {

// a general mesh: N_node at x in the cell that holds x (0 when node is not one of its
// nodes; the basis is continuous, so on a shared edge either cell gives the same value)
static double meshBasis(const Mesh& mesh, int node, const Vector2d& x) {
  const int e = cellOf(mesh, x);
  const int a = localNode(mesh, e, node);
  return a < 0 ? 0.0 : cellBasis(mesh, e, x).N[a];
}

double gridBasis(const Mesh& mesh, int node, const Vector2d& x) {
  if (!mesh.regular()) return meshBasis(mesh, node, x);
  return SvpMPM(x(0) - mesh.coord(node, 0), mesh.h(0)).S * SvpMPM(x(1) - mesh.coord(node, 1), mesh.h(1)).S;
}

static void cpdiBasis(const Mesh& mesh, MaterialPoint& mp) {
  const Corners x = domainCorners(mp);
  for (int v = 0; v < mp.nn; ++v) {
    Eigen::Vector4d Sc;  // grid basis of node v at the four corners
    for (int c = 0; c < 4; ++c) Sc(c) = gridBasis(mesh, mp.nIN[v], x.col(c));
    const Basis2D b = (mp.mpType == MpType::CPDI1) ? SvpCPDI1(Sc, mp.st) : SvpCPDI2(Sc, x);
    mp.Svp[v] = b.S;
    mp.dSvp.col(v) = b.dS;
  }
}

// a general mesh: CPDI from the cell basis at the corners (each corner's cell searched once)
static void cpdiMeshBasis(const Mesh& mesh, MaterialPoint& mp) {
  const Corners x = domainCorners(mp);
  int ec[4];
  CellBasis bc[4];
  for (int c = 0; c < 4; ++c) {
    ec[c] = findCell(mesh, x.col(c));  // just past the mesh edge: the cell of the moved corner
    if (ec[c] < 0) ec[c] = cellOf(mesh, x.col(c) + 1e-6 * (mp.mpC - x.col(c)));
    bc[c] = cellBasis(mesh, ec[c], x.col(c));
  }
  for (int v = 0; v < mp.nn; ++v) {
    Eigen::Vector4d Sc;  // cell basis of node v at the four corners
    for (int c = 0; c < 4; ++c) {
      const int a = localNode(mesh, ec[c], mp.nIN[v]);
      Sc(c) = a < 0 ? 0.0 : bc[c].N[a];
    }
    const Basis2D b = (mp.mpType == MpType::CPDI1) ? SvpCPDI1(Sc, mp.st) : SvpCPDI2(Sc, x);
    mp.Svp[v] = b.S;
    mp.dSvp.col(v) = b.dS;
  }
}

// a general mesh: standard MPM from the basis of the point's one cell (cellBasis);
// GIMP needs the regular grid
static void meshMPMbasis(const Mesh& mesh, MaterialPoint& mp) {
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

void MPMbasis(const Mesh& mesh, MaterialPoint& mp) {
  if (!mesh.regular()) return isCPDI(mp) ? cpdiMeshBasis(mesh, mp) : meshMPMbasis(mesh, mp);
  if (isCPDI(mp)) return cpdiBasis(mesh, mp);
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

}  // namespace ample
