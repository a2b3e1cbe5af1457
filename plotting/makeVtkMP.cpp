//--------------------------------------------------------------------------
// makeVtkMP — legacy VTK file of the material points of one load step
//--------------------------------------------------------------------------
// See makeVtkMP.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "makeVtkMP.h"
#include "makeVtk.h"
#include <cmath>
#include <functional>
#include <sstream>

namespace ample {

void makeVtkMP(const std::vector<MaterialPoint>& mpData, const std::string& path) {
  const size_t nmp = mpData.size();
  std::ostringstream s;
  s.precision(15);
  s << "# vtk DataFile Version 2.0\nample-cpp material points\nASCII\n"
    << "DATASET UNSTRUCTURED_GRID\nPOINTS " << nmp << " double\n";
  for (const MaterialPoint& mp : mpData) s << mp.mpC(0) << " " << mp.mpC(1) << " 0\n";
  s << "CELLS " << nmp << " " << 2 * nmp << "\n";
  for (size_t p = 0; p < nmp; ++p) s << "1 " << p << "\n";
  s << "CELL_TYPES " << nmp << "\n";
  for (size_t p = 0; p < nmp; ++p) s << "1\n";  // VTK_VERTEX
  s << "POINT_DATA " << nmp << "\nVECTORS displacement double\n";
  for (const MaterialPoint& mp : mpData) s << mp.u(0) << " " << mp.u(1) << " 0\n";
  auto scalar = [&](const char* name, const std::function<double(const MaterialPoint&)>& f) {
    s << "SCALARS " << name << " double 1\nLOOKUP_TABLE default\n";
    for (const MaterialPoint& mp : mpData) s << f(mp) << "\n";
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
  atomicWrite(path, s.str());
}

}  // namespace ample
