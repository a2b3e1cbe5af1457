//--------------------------------------------------------------------------
// dirichletBand — the Dirichlet function d(phi) of eq 16 and its band integrals
//--------------------------------------------------------------------------
// See dirichletBand.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "dirichletBand.h"
#include "constitutive/exercise.h"
#include <cassert>

namespace ample {

double dirichletD(double phi, double delta) {
  assert(delta > 0 && "dirichletD: the band width delta must be positive");
  // BEGIN EXERCISE dirichletBand
  if (phi < 0) return 0.0;      // outside the solid
  if (phi > delta) return 1.0;  // inside, beyond the band
  const double r = 1.0 - phi / delta;
  return 1.0 - r * r;           // eq 16
  // END EXERCISE
}

double dirichletDPrime(double phi, double delta) {
  assert(delta > 0 && "dirichletDPrime: the band width delta must be positive");
  // BEGIN EXERCISE dirichletBand
  if (phi < 0 || phi > delta) return 0.0;
  return 2.0 / delta * (1.0 - phi / delta);  // d/dphi of eq 16
  // END EXERCISE
}

Vector2d dirichletGrad(double phi, double delta, const Vector2d& n) {
  return dirichletDPrime(phi, delta) * n;  // grad phi = n for a straight boundary
}

// with s = phi/delta: d = 2s - s^2, d' = (2/delta)(1 - s), dphi = delta ds
BandIntegrals bandIntegrals(double delta) {
  assert(delta > 0 && "bandIntegrals: the band width delta must be positive");
  BandIntegrals I;
  I.dp = 1.0;                   // d(delta) - d(0)
  I.d_dp = 0.5;                 // [d^2/2] from 0 to delta
  I.dp_dp = 4.0 / (3.0 * delta);  // (4/delta^2) int (1-s)^2 delta ds
  I.d = 2.0 * delta / 3.0;      // delta int (2s - s^2) ds
  I.d_d = 8.0 * delta / 15.0;   // delta int (1 - u^2)^2 du, u = 1 - s
  return I;
}

}  // namespace ample
