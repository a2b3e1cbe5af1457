//--------------------------------------------------------------------------
// postPro — VTK output of a converged load step
//--------------------------------------------------------------------------
// [AMPLE] sec 5.2 (fig 13): every vtkEvery load steps mpData_<lstp>.vtk (the
// points); mesh.vtk (the grid alone) once, with the first; and mesh_<lstp>.vtk
// (the grid of that step with its nodal displacements uvw, as AMPLE writes it)
// only when gridEachStep: the grid moves (fem=1, or a setup that rebuilds it,
// Analysis::gridMoves) or `--vtk-grid every` asks for it. A grid that stays put
// is the same in every step: readers take mesh.vtk when mesh_<lstp>.vtk is not
// there. Nothing when vtkEvery = 0. All ASCII or all BINARY (format, from
// --vtk-format; makeVtkWriter.h).
// Inputs:  mesh · mpData · uvw (nDoF) converged increment of the step · lstp ·
//          vtkEvery · outDir · format · gridEachStep
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
             VtkFormat format = VtkFormat::Ascii, bool gridEachStep = true);

}  // namespace ample
