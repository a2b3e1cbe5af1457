//--------------------------------------------------------------------------
// postPro — VTK output of a converged load step
//--------------------------------------------------------------------------
// Seed 002 sec 5.2 (fig 13): mesh.vtk once (the grid does not change) and
// mpData_<lstp>.vtk every vtkEvery load steps; nothing
// when vtkEvery = 0.
// Inputs:  mesh · mpData · lstp · vtkEvery · outDir
// Outputs: files in outDir
// Tests:   tests/test_output.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"
#include <string>

namespace ample {

void postPro(const Mesh& mesh, const std::vector<MaterialPoint>& mpData, int lstp, int vtkEvery,
             const std::string& outDir);

}  // namespace ample
