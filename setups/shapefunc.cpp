//--------------------------------------------------------------------------
// shapefunc — bi-linear finite element shape functions of a quadrilateral
//--------------------------------------------------------------------------
// See shapefunc.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "shapefunc.h"

namespace ample {

Eigen::Vector4d shapefunc(const Vector2d& xsi) {
  const double x = xsi(0), y = xsi(1);
  return Eigen::Vector4d((1 - x) * (1 - y), (1 + x) * (1 - y), (1 + x) * (1 + y),
                         (1 - x) * (1 + y)) / 4.0;
}

}  // namespace ample
