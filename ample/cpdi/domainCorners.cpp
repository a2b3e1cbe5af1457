//--------------------------------------------------------------------------
// domainCorners — the four corners of a material point's domain
//--------------------------------------------------------------------------
// See domainCorners.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "domainCorners.h"

namespace ample {

Corners domainCorners(const MaterialPoint& mp) {
  const double a[4] = {-1, 1, 1, -1}, b[4] = {-1, -1, 1, 1};  // corner signs
  Corners x;
  for (int c = 0; c < 4; ++c) {
    switch (mp.mpType) {
      case MpType::MPM: x.col(c) = mp.mpC; break;
      case MpType::GIMP: x.col(c) = mp.mpC + Vector2d(a[c] * mp.lp(0), b[c] * mp.lp(1)); break;
      case MpType::CPDI1: x.col(c) = mp.mpC + 0.5 * (a[c] * mp.cpdi->st.col(0) + b[c] * mp.cpdi->st.col(1)); break;
      case MpType::CPDI2: x.col(c) = mp.cpdi->xc.col(c); break;
    }
  }
  return x;
}

double quadArea(const Corners& x) {
  double A = 0.0;  // shoelace formula
  for (int c = 0; c < 4; ++c) A += x(0, c) * x(1, (c + 1) % 4) - x(0, (c + 1) % 4) * x(1, c);
  return 0.5 * A;
}

}  // namespace ample
