//--------------------------------------------------------------------------
// makeVtk — legacy VTK file of the background grid
//--------------------------------------------------------------------------
// [AMPLE] sec 5.2 (fig 13): an unstructured grid of quads (z = 0), readable
// by ParaView and VisIt, with the nodal displacements uvw of a load step as
// point data when given (mesh_<lstp>.vtk; none for mesh.vtk). Written to a
// temporary name, then renamed. ASCII (reals as "double", 15 digits) or BINARY
// (big-endian 4-byte "float" and int; makeVtkWriter.h), the same sections.
// Inputs:  mesh (coord, etpl) · path · uvw (nDoF, or empty) · format
// Outputs: the file at path
// Tests:   tests/test_output.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"
#include "makeVtkWriter.h"
#include <string>

namespace ample {

void makeVtk(const Mesh& mesh, const std::string& path, const Eigen::VectorXd& uvw = Eigen::VectorXd(),
             VtkFormat format = VtkFormat::Ascii);

// write `text` to path.tmp and rename it to path, so that a file that exists
// is complete; throws RunError when the file cannot be written
void atomicWrite(const std::string& path, const std::string& text);

}  // namespace ample
