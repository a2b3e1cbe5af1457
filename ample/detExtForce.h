//--------------------------------------------------------------------------
// detExtForce — nodal external forces from body forces and point forces
//--------------------------------------------------------------------------
// [AMPLE] eqs 27-28 and 32: f_ext = sum_p [S_vp]^T (m_p {0, -g} + f_p),
// the full load; the main loop scales it by the load factor lstp/lstps.
// Gravity acts in -y. Uses the basis functions of the start of the step.
// detBodyForce: a body force given as a function of position (the
// manufactured solution of [Lagrangian] sec 7.4): f_ext = sum_p [S_vp]^T b(X_p, lf) V0_p,
// b per unit original volume (the nominal body force J b, N/m3) at the point's
// original position X_p (mp.X0): a dead load carried by each point's material,
// like its weight m_p g, so it does not change in the Newton passes of a step.
// It is the full force at load factor lf (the function decides how it grows).
// Inputs:  nDoF · g (m/s2) · mpData (nIN, Svp, mpM, fp) | b · lf · mpData (nIN, Svp, X0, vp0)
// Outputs: fext (nDoF)
// Tests:   tests/test_detExtForce.cpp
//--------------------------------------------------------------------------
#pragma once
#include "mpData.h"
#include <functional>

namespace ample {

Eigen::VectorXd detExtForce(int nDoF, double g, const std::vector<MaterialPoint>& mpData);

Eigen::VectorXd detBodyForce(int nDoF, const std::function<Vector2d(const Vector2d&, double)>& b,
                             double lf, const std::vector<MaterialPoint>& mpData);

}  // namespace ample
