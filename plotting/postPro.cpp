//--------------------------------------------------------------------------
// postPro — VTK output of a converged load step
//--------------------------------------------------------------------------
// See postPro.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "postPro.h"
#include "makeVtk.h"
#include "makeVtkMP.h"

namespace ample {

void postPro(const Mesh& mesh, const std::vector<MaterialPoint>& mpData, const Eigen::VectorXd& uvw,
             int lstp, int vtkEvery, const std::string& outDir, VtkFormat format, bool gridEachStep) {
  if (vtkEvery <= 0 || lstp % vtkEvery != 0) return;
  if (lstp == vtkEvery) makeVtk(mesh, outDir + "/mesh.vtk", Eigen::VectorXd(), format);
  if (gridEachStep) makeVtk(mesh, outDir + "/mesh_" + std::to_string(lstp) + ".vtk", uvw, format);
  makeVtkMP(mpData, outDir + "/mpData_" + std::to_string(lstp) + ".vtk", format);
}

}  // namespace ample
