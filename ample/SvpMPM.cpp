//--------------------------------------------------------------------------
// SvpMPM — one-dimensional standard MPM basis function and its gradient
//--------------------------------------------------------------------------
// Seed 002 eqs 23-24. See SvpMPM.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "SvpMPM.h"

namespace ample {

Basis1D SvpMPM(double d, double h) {
  if (-h < d && d <= 0.0) return {1.0 + d / h, 1.0 / h};
  if (0.0 < d && d <= h) return {1.0 - d / h, -1.0 / h};
  return {0.0, 0.0};
}

}  // namespace ample
