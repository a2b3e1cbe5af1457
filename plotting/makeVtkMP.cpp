//--------------------------------------------------------------------------
// makeVtkMP — legacy VTK file of the material points of one load step
//--------------------------------------------------------------------------
// See makeVtkMP.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "makeVtkMP.h"
#include "makeVtk.h"
#include <cmath>
#include <functional>

namespace ample {

void makeVtkMP(const std::vector<MaterialPoint>& mpData, const std::string& path, VtkFormat format) {
  const size_t nmp = mpData.size();
  const std::string n = std::to_string(nmp);
  VtkWriter w(format, "ample-cpp material points", "UNSTRUCTURED_GRID", path);
  auto perPoint = [&](int width, const std::function<double(const MaterialPoint&, int)>& f) {
    std::vector<double> v(width * nmp);
    for (size_t p = 0; p < nmp; ++p)
      for (int c = 0; c < width; ++c) v[width * p + c] = f(mpData[p], c);
    w.reals(v, width);
  };
  w.line("POINTS " + n + " " + w.realType());
  perPoint(3, [](const MaterialPoint& mp, int c) { return c < 2 ? mp.mpC(c) : 0.0; });  // z = 0
  w.line("CELLS " + n + " " + std::to_string(2 * nmp));
  std::vector<int> cells(2 * nmp, 1);                       // "1 p": one node, point p
  for (size_t p = 0; p < nmp; ++p) cells[2 * p + 1] = int(p);
  w.ints(cells, 2);
  w.line("CELL_TYPES " + n);
  w.ints(std::vector<int>(nmp, 1), 1);                      // VTK_VERTEX
  w.line("POINT_DATA " + n);
  w.line(std::string("VECTORS displacement ") + w.realType());
  perPoint(3, [](const MaterialPoint& mp, int c) { return c < 2 ? mp.u(c) : 0.0; });
  auto scalar = [&](const char* name, const std::function<double(const MaterialPoint&)>& f) {
    w.line(std::string("SCALARS ") + name + " " + w.realType() + " 1");
    w.line("LOOKUP_TABLE default");
    perPoint(1, [&f](const MaterialPoint& mp, int) { return f(mp); });
  };
  scalar("ux", [](const MaterialPoint& mp) { return mp.u(0); });
  scalar("uy", [](const MaterialPoint& mp) { return mp.u(1); });
  const char* sigName[6] = {"sigma_xx", "sigma_yy", "sigma_zz", "sigma_xy", "sigma_yz", "sigma_zx"};
  for (int c = 0; c < 6; ++c) scalar(sigName[c], [c](const MaterialPoint& mp) { return mp.sig(c); });
  scalar("rho_vonMises", [](const MaterialPoint& mp) {
    const double p = mp.sig.head<3>().sum() / 3.0;
    return std::sqrt((mp.sig.head<3>().array() - p).square().sum() + 2 * mp.sig.tail<3>().squaredNorm());
  });
  scalar("volume", [](const MaterialPoint& mp) { return mp.vp; });
  scalar("lpx", [](const MaterialPoint& mp) { return mp.lp(0); });
  scalar("lpy", [](const MaterialPoint& mp) { return mp.lp(1); });
  w.finish();
}

}  // namespace ample
