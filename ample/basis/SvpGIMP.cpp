//--------------------------------------------------------------------------
// SvpGIMP — one-dimensional GIMP basis function and its gradient
//--------------------------------------------------------------------------
// [AMPLE] eqs 25-26. See SvpGIMP.h for the regions, inputs and outputs.
//--------------------------------------------------------------------------
#include "SvpGIMP.h"
#include "constitutive/exercise.h"

namespace ample {

Basis1D SvpGIMP(double d, double h, double l) {
  if (l <= 0.0) return SvpMPM(d, h);
  // BEGIN EXERCISE SvpGIMP
  if (-h - l < d && d <= -h + l)  // A
    return {(h + l + d) * (h + l + d) / (4 * h * l), (h + l + d) / (2 * h * l)};
  if (-h + l < d && d <= -l)      // B
    return {1 + d / h, 1 / h};
  if (-l < d && d <= l)           // C
    return {1 - (d * d + l * l) / (2 * h * l), -d / (h * l)};
  if (l < d && d <= h - l)        // D
    return {1 - d / h, -1 / h};
  if (h - l < d && d <= h + l)    // E
    return {(h + l - d) * (h + l - d) / (4 * h * l), -(h + l - d) / (2 * h * l)};
  return {0.0, 0.0};
  // END EXERCISE
}

}  // namespace ample
