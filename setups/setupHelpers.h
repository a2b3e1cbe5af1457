//--------------------------------------------------------------------------
// setupHelpers — material point generation and boundary conditions for setups
//--------------------------------------------------------------------------
// [AMPLE] sec 5.2 (fig 11): points are placed mp x mp per cell of a block of
// cells (detMpPos local positions mapped by shapefunc), cell by cell (x
// fastest); each gets the domain half lengths h/(2 mp) (GIMP; 0 for MPM),
// volume (h_x/mp)(h_y/mp) (unit thickness) and mass rho V; a CPDI point its
// rectangle as its domain (cpdi: s, t and the corners; none for MPM and GIMP).
// fillPolygon ([Boundaries] sec 4, fig 4): the same points over the block, then
// each point's square domain is clipped by the solid polygon (clipPolygon):
// wholly outside (less than 1e-12 of it inside): removed; wholly inside (more
// than 1 - 1e-12): kept as fillBlock makes it; otherwise truncated: volume =
// the area inside, position = the centroid of that area, half lengths scaled
// by sqrt(area fraction) (so 4 lp_x lp_y = V still) about the new position.
// addBoundary: an implicit boundary (boundary.h) with one type for every
// segment or one per segment, band width delta = deltaOverH h (h the smaller
// spacing; [Boundaries]: 1e-6), the solid on the left by default; returns it so
// that a setup can set du. solidPolygon: the polygon round the solid, the
// points of the boundaries in their order (a gap between two boundaries is a
// free edge of the solid), so a setup lists them anticlockwise round it.
// Inputs:  block corner (x0, y0), its cells (nelsx, nelsy), spacing h,
//          the setup's mp, mpType, cmType, E, nu, rhoY (Common) · density rho · solid polygon
// Outputs: points appended to mpData; fixDofs adds Dirichlet conditions;
//          addBoundary appends to an.boundaries
// Tests:   tests/test_ample.cpp (setups run), tests/test_detMPs.cpp,
//          tests/test_boundary.cpp (fillPolygon, addBoundary, solidPolygon)
//--------------------------------------------------------------------------
#pragma once
#include "ample/boundaries/boundary.h"
#include "ample/meshes/clipPolygon.h"
#include "setups.h"
#include <functional>

namespace ample {

// an Analysis with the settings every setup shares: lstps, tol, NRitMax, solver, the remedies,
// formulation, domainUpdate, locking, geostatic, K0 (g is set by the setups that have gravity)
Analysis baseAnalysis(const Common& p);

// a parameter value as the command line takes it, e.g. number(32) = "32", number(0.01) = "0.01"
std::string number(double v);

// InputError before any work when `points` material points (sizeof(MaterialPoint) each, its
// basis inside) exceed the memory this machine has available
void checkPointMemory(size_t points);
void fillBlock(std::vector<MaterialPoint>& mpData, const Vector2d& corner, int nelsx, int nelsy,
               const Vector2d& h, const Common& p, double rho);

// fillBlock's points, with those outside `solid` removed and those cut by it truncated
void fillPolygon(std::vector<MaterialPoint>& mpData, const Vector2d& corner, int nelsx,
                 int nelsy, const Vector2d& h, const Common& p, double rho,
                 const Polygon& solid);

// points in every cell of a general mesh (docs/meshes.md, finite element mode):
// quadrilaterals: 2 x 2, at the Gauss positions xi, eta = +-1/sqrt(3) with V = det J(xi)
// (weight 1) for standard MPM, or with the four sub-quadrilaterals of the cell (split at
// xi = 0, eta = 0) as domains for CPDI1 / CPDI2 (point at the sub-cell's centre,
// xi = +-1/2; V = its area; CPDI1: s, t join its mid-edges); triangles: triPoints = 1
// (centroid, V = A) or 3 (at 2/3, 1/6, 1/6, V = A/3), standard MPM only
// one point at x of volume V; CPDI1/CPDI2: a square domain of that area about x (MPM: none)
MaterialPoint cellPoint(const Vector2d& x, double V, const Common& p, double rho);
void fillCells(std::vector<MaterialPoint>& mpData, const Mesh& mesh, const Common& p, double rho,
               int triPoints = 3);

// the reactions of a set of nodes (frct: nDoF, as Analysis::frct): their vector sum and
// the sum of their magnitudes, f = sum_n |(frct_x, frct_y)_n| ([CPDI] sec 3.2, fig 7)
struct Reaction {
  Vector2d sum = Vector2d::Zero();
  double magnitudes = 0;
};
Reaction reactionOver(const Eigen::VectorXd& frct, const std::vector<int>& nodes);

// an implicit boundary through the points x, e.g.
//   addBoundary(an, {{0, 0}, {1, 0.5}}, BoundaryType::Roller);
//   addBoundary(an, {{1, 1}, {0, 1}}, BoundaryType::Prescribed).du = {{0, -0.05}};
Boundary& addBoundary(Analysis& an, std::vector<Vector2d> x, BoundaryType type,
                      double deltaOverH = 1e-6, SolidSide solid = SolidSide::Left);
Boundary& addBoundary(Analysis& an, std::vector<Vector2d> x, std::vector<BoundaryType> type,
                      double deltaOverH = 1e-6, SolidSide solid = SolidSide::Left);

// rotation by theta degrees (anticlockwise), exact at multiples of 90 (so that a model turned
// by 90 degrees is the same discretisation)
Eigen::Matrix2d rotationDegrees(double theta);

// the parameters of every setup with implicit boundaries: the common ones with the settings of
// [Boundaries]'s examples (sec 5): standard MPM, small strain (SS), E = 1000 MPa, nu = 0.3,
// tol = 1e-8 (the IB residual floor is ~2e-9 at delta = 1e-6 h); and delta (band width / h,
// eq 16) and ibK2 (the K2 coupling: paper or consistent), which ibSettings gives an's boundaries
struct IbCommon : Common {
  double delta = 1e-6;
  IbCoupling ibK2 = IbCoupling::Consistent;
  IbCommon() {
    tol = 1e-8;
    mpType = MpType::MPM;
    formulation = Formulation::SS;
    E = 1e9;
    nu = 0.3;
  }
};
Params ibCommonParams(IbCommon& p);  // commonParams, then delta and ibK2
void ibSettings(Analysis& an, const IbCommon& p);

// the polygon round the solid: the points of the boundaries, in order
Polygon solidPolygon(const std::vector<Boundary>& boundaries);

// constrain direction i (0 = x, 1 = y) of every node where `where(X, Y)` holds
void fixDofs(Mesh& mesh, int i, const std::function<bool(double, double)>& where,
             double value = 0.0);

}  // namespace ample
