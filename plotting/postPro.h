//--------------------------------------------------------------------------
// postPro — VTK output of a converged load step
//--------------------------------------------------------------------------
// [AMPLE] sec 5.2 (fig 13): every vtkEvery load steps mpData_<lstp>.vtk (the
// points) and mesh_<lstp>.vtk (the grid of that step with its nodal
// displacements uvw, as AMPLE writes it; a grid that moves, as the stretch's,
// is written as it is in that step); mesh.vtk (the grid alone) once, with the
// first; nothing when vtkEvery = 0. All three ASCII or all BINARY (format,
// from --vtk-format; makeVtkWriter.h).
// Inputs:  mesh · mpData · uvw (nDoF) converged increment of the step · lstp ·
//          vtkEvery · outDir · format
// Outputs: files in outDir
// Tests:   tests/test_output.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"
#include "makeVtkWriter.h"
#include <string>

namespace ample {

void postPro(const Mesh& mesh, const std::vector<MaterialPoint>& mpData, const Eigen::VectorXd& uvw,
             int lstp, int vtkEvery, const std::string& outDir,
             VtkFormat format = VtkFormat::Ascii);

}  // namespace ample
