//--------------------------------------------------------------------------
// detExtForce — nodal external forces from body forces and point forces
//--------------------------------------------------------------------------
// Seed 002 eqs 27-28 and 32: f_ext = sum_p [S_vp]^T (m_p {0, -g} + f_p),
// the full load; the main loop scales it by the load factor lstp/lstps.
// Gravity acts in -y. Uses the basis functions of the start of the step.
// Inputs:  nDoF · g (m/s2) · mpData (nIN, Svp, mpM, fp)
// Outputs: fext (nDoF)
// Tests:   tests/test_detExtForce.cpp
//--------------------------------------------------------------------------
#pragma once
#include "mpData.h"

namespace ample {

Eigen::VectorXd detExtForce(int nDoF, double g, const std::vector<MaterialPoint>& mpData);

}  // namespace ample
