//--------------------------------------------------------------------------
// readGmsh — a background mesh drawn in Gmsh, read from a .msh file
//--------------------------------------------------------------------------
// docs/meshes.md ("A mesh from Gmsh"). Reads Gmsh's own format, version 4.1
// ASCII (what `gmsh -2 file.geo` writes): the sections $MeshFormat,
// $PhysicalNames, $Entities, $Nodes and $Elements. The cells are the 2D
// elements of type 2 (linear triangle) or 3 (bilinear quadrilateral), one type
// per mesh; a cell that Gmsh wrote clockwise is turned round (generalMesh
// wants anticlockwise cells). The nodes that the cells use are numbered 0, 1,
// ... in the order of their Gmsh tags. Each physical group (of points, curves
// or surfaces, named in $PhysicalNames or else "dim:tag") gives the set of the
// mesh nodes on it: the nodes of the boundary conditions of a setup.
// Inputs:  path of the .msh file
// Outputs: GmshMesh: mesh (generalMesh: type, coord, etpl) · groups (name ->
//          node numbers, ascending); InputError naming the file and what is
//          wrong (missing file, another version or binary, 3D or curved
//          elements, both cell types, z != 0, a node tag without a node)
// Tests:   tests/test_readGmsh.cpp (the shipped setups/meshes/plate*.msh)
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"
#include <map>
#include <string>
#include <vector>

namespace ample {

struct GmshMesh {
  Mesh mesh;                                        // the 2D cells as a general mesh
  std::map<std::string, std::vector<int>> groups;   // physical group -> its nodes (0-based)
};

GmshMesh readGmsh(const std::string& path);

}  // namespace ample
