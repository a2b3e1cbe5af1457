//--------------------------------------------------------------------------
// makeVtk — legacy VTK file of the background grid
//--------------------------------------------------------------------------
// See makeVtk.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "makeVtk.h"
#include "ample/errors.h"
#include <cstdio>
#include <fstream>
#include <sstream>

namespace ample {

void atomicWrite(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary);
    f << text;
    f.close();
    if (!f) throw RunError("cannot write " + tmp);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw RunError("cannot rename " + tmp);
}

void makeVtk(const Mesh& mesh, const std::string& path, const Eigen::VectorXd& uvw) {
  std::ostringstream s;
  s.precision(15);
  s << "# vtk DataFile Version 2.0\nample-cpp background mesh\nASCII\n"
    << "DATASET UNSTRUCTURED_GRID\nPOINTS " << mesh.nodes() << " double\n";
  for (int n = 0; n < mesh.nodes(); ++n) s << mesh.coord(n, 0) << " " << mesh.coord(n, 1) << " 0\n";
  s << "CELLS " << mesh.nels() << " " << mesh.nels() * (mesh.cellNodes() + 1) << "\n";
  for (int e = 0; e < mesh.nels(); ++e) {
    s << mesh.cellNodes();
    for (int a = 0; a < mesh.cellNodes(); ++a) s << " " << mesh.etpl(e, a);
    s << "\n";
  }
  s << "CELL_TYPES " << mesh.nels() << "\n";
  const char* type = mesh.cellNodes() == 3 ? "5\n" : "9\n";  // VTK_TRIANGLE, VTK_QUAD
  for (int e = 0; e < mesh.nels(); ++e) s << type;
  if (uvw.size() == mesh.nDoF()) {
    s << "POINT_DATA " << mesh.nodes() << "\nVECTORS displacement double\n";
    for (int n = 0; n < mesh.nodes(); ++n) s << uvw(dof(n, 0)) << " " << uvw(dof(n, 1)) << " 0\n";
  }
  atomicWrite(path, s.str());
}

}  // namespace ample
