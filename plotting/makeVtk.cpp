//--------------------------------------------------------------------------
// makeVtk — legacy VTK file of the background grid
//--------------------------------------------------------------------------
// See makeVtk.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "makeVtk.h"
#include "ample/errors.h"
#include <cstdio>
#include <fstream>

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

void makeVtk(const Mesh& mesh, const std::string& path, const Eigen::VectorXd& uvw, VtkFormat format) {
  VtkWriter w(format, "ample-cpp background mesh", "UNSTRUCTURED_GRID", path);
  const int nn = mesh.nodes(), ne = mesh.nels(), cn = mesh.cellNodes();
  w.line("POINTS " + std::to_string(nn) + " " + w.realType());
  std::vector<double> xyz(3 * size_t(nn), 0.0);             // z = 0
  for (int n = 0; n < nn; ++n) xyz[3 * n] = mesh.coord(n, 0), xyz[3 * n + 1] = mesh.coord(n, 1);
  w.reals(xyz, 3);
  w.line("CELLS " + std::to_string(ne) + " " + std::to_string(ne * (cn + 1)));
  std::vector<int> cells;
  cells.reserve(size_t(ne) * (cn + 1));
  for (int e = 0; e < ne; ++e) {
    cells.push_back(cn);
    for (int a = 0; a < cn; ++a) cells.push_back(mesh.etpl(e, a));
  }
  w.ints(cells, cn + 1);
  w.line("CELL_TYPES " + std::to_string(ne));
  w.ints(std::vector<int>(size_t(ne), cn == 3 ? 5 : 9), 1);  // VTK_TRIANGLE, VTK_QUAD
  if (uvw.size() == mesh.nDoF()) {
    w.line("POINT_DATA " + std::to_string(nn));
    w.line(std::string("VECTORS displacement ") + w.realType());
    std::vector<double> u(3 * size_t(nn), 0.0);
    for (int n = 0; n < nn; ++n) u[3 * n] = uvw(dof(n, 0)), u[3 * n + 1] = uvw(dof(n, 1));
    w.reals(u, 3);
  }
  w.finish();
}

}  // namespace ample
