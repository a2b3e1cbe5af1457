//--------------------------------------------------------------------------
// MPMbasis — two-dimensional basis functions and gradients of one point
//--------------------------------------------------------------------------
// [AMPLE] eq 22 and footnote 3: S(X,Y) = S(X) S(Y),
// dS/dX = dS(X) S(Y), dS/dY = S(X) dS(Y), from SvpMPM (mpType 1, eqs 23-24)
// or SvpGIMP (mpType 2, eqs 25-26) in each direction. CPDI1/CPDI2 (mpType 3/4,
// [CPDI] sec 2 (iv)): SvpCPDI from the grid basis at the domain corners.
// MPMbasis is the regular grid's; meshMPMbasis the same on a general mesh
// (docs/meshes.md): MPM from the cell basis of the point's cell (cellBasis:
// barycentric / inverse isoparametric map, grad N = J^-T dN/dxi); CPDI from the
// cell basis at each corner in the cell that holds it (a corner outside the
// mesh: cornerCell, the basis continued); GIMP: InputError. elemMPinfo calls
// one or the other. gridBasis: the grid node's bi-linear N_node(x). cornerBasis
// (either mesh): the basis of each of the point's nodes at each domain corner,
// S(v, c) = N_nIN[v](x_c) (SvpCPDI's Sc; the CPDI2 corner update; detFDoFs).
// Inputs:  coord (nodes x 2) · mp.nIN, mp.nn, mp.mpC, mp.lp, mp.mpType (CPDI: mp.cpdi) · h (2)
// Outputs: mp.Svp (nn) · mp.dSvp (2 x nn), gradients with respect to X~ (start of step),
//          of its first nn entries (elemMPinfo; by hand: set mp.nn, mp.nIN)
// Tests:   tests/test_basis.cpp
//--------------------------------------------------------------------------
#pragma once
#include "domainCorners.h"
#include "ample/mpData.h"

namespace ample {

void MPMbasis(const Mesh& mesh, MaterialPoint& mp);                // the regular grid
void meshMPMbasis(const Mesh& mesh, MaterialPoint& mp);            // a general mesh
double gridBasis(const Mesh& mesh, int node, const Vector2d& x);  // bi-linear grid basis N_node(x)
using CornerBasis = Eigen::Matrix<double, MAXN, 4>;                // S(v, c): node v, corner c
CornerBasis cornerBasis(const Mesh& mesh, const MaterialPoint& mp, const Corners& x);

}  // namespace ample
