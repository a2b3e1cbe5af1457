//--------------------------------------------------------------------------
// SvpMPM — one-dimensional standard MPM basis function and its gradient
//--------------------------------------------------------------------------
// [AMPLE] eqs 23-24. See SvpMPM.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "SvpMPM.h"
#include "constitutive/exercise.h"

namespace ample {

// The gradient's side: a point within t = 1e-9 h of the node is taken to be on it
// (round-off in a position that should sit on a grid line must not decide the side;
// elemForMP uses the same t, so the point's cell and the branch of each node's
// gradient agree). The value S is continuous and is left as eq 23 gives it.
Basis1D SvpMPM(double d, double h) {
  // BEGIN EXERCISE SvpMPM
  const double S = (-h < d && d <= 0.0) ? 1.0 + d / h : (0.0 < d && d <= h) ? 1.0 - d / h : 0.0;
  const double t = 1e-9 * h;
  if (-h + t < d && d <= t) return {S, 1.0 / h};
  if (t < d && d <= h + t) return {S, -1.0 / h};
  return {S, 0.0};
  // END EXERCISE
}

}  // namespace ample
