//--------------------------------------------------------------------------
// elemMPinfoMesh — elemMPinfo on a general mesh of triangles or quadrilaterals
//--------------------------------------------------------------------------
// docs/meshes.md. Replaces the core's elemMPinfo as a whole where the program
// chooses it (a general mesh without CPDI points; setups/program/run.cpp): the
// cell search is built for the mesh as it is (buildCellSearch: a setup may have
// moved its nodes), then per point (meshPointInfo) the one cell that holds it
// (meshElemForMP: cellOf; keepCells, the finite element mode: a point keeps the
// cell it has, no search), that cell's nodes (nodesForMP), S_vp and dS_vp from
// the cell's basis at the point (meshMPMbasis: cellBasis, barycentric or inverse
// isoparametric, grad N = J^-T dN/dxi), its null nodes unlinked (dropNullNodes);
// then the active cells (markActiveCells). A point with a domain (lp > 0, GIMP)
// needs the grid: InputError.
// dropNullNodes: unlink the nodes whose S and dS at the point are both exactly
// zero: they carry no mass, force or stiffness from it, and linked they would put a
// dof with an empty stiffness column into the system. A point on a quadrilateral's
// corner has them (cellBasis puts a coordinate within 1e-14 of an edge on it), and
// a CPDI point whose corner lies on the far edge of its cell (ample/cpdi/); on the
// grid a GIMP or MPM point never does (its cells are those it overlaps).
// Inputs:  mesh (type, coord, etpl) · mpData (mpC, lp, mpType; eIN, ne when keepCells)
// Outputs: mpData (eIN, ne, nIN, nn, Svp, dSvp) · mesh.search, mesh.eInA;
//          RunError naming the point that left the mesh
// Tests:   tests/test_mesh.cpp, tests/test_femode.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"

namespace ample {

void elemMPinfoMesh(Mesh& mesh, std::vector<MaterialPoint>& mpData, bool keepCells = false);

// its parts (for elemMPinfoCPDI, elemMPinfoFast)
void meshPointInfo(const Mesh& mesh, MaterialPoint& mp, size_t p, bool keepCells);  // point p
int meshElemForMP(const Mesh& mesh, const Vector2d& mpC, const Vector2d& lp, std::array<int, MAXE>& eIN);
void meshMPMbasis(const Mesh& mesh, MaterialPoint& mp);  // standard MPM: Svp, dSvp of its nn nodes
int dropNullNodes(MaterialPoint& mp);                    // unlink nodes with S = 0 and dS = 0; the new nn

}  // namespace ample
