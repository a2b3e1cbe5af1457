// testProblems.h — small problems built in code for the tests (not a test file itself)
#pragma once
#include "ample/detMPs.h"
#include "ample/elemMPinfo.h"
#include "ample/formCoord2D.h"
#include "setups/setupHelpers.h"
#include "setups/setups.h"
#include <fstream>
#include <random>
#include <string>

namespace ample::testing {

// a 4 x 4 grid of 1 m cells with an mp x mp block of points filling cells [1,3) x [1,3)
inline Analysis smallBlock(MpType mpType, CmType cmType, int mp = 2) {
  Params P = commonParams(1);
  setDefault(P, "mp", mp);
  setDefault(P, "mpType", int(mpType));
  setDefault(P, "cmType", int(cmType));
  setDefault(P, "E", 1e6);
  setDefault(P, "nu", 0.3);
  setDefault(P, "rhoY", 2e3);
  Analysis an;
  an.mesh = formCoord2D(4, 4, 4.0, 4.0);
  fillBlock(an.mpData, Vector2d(1, 1), 2, 2, an.mesh.h, P, 1000.0);
  return an;
}

// give every point a converged, non-trivial state (Fn, epsEn) so that stress,
// geometric stiffness and (for von Mises) plastic flow all enter the tangent
inline void prestrain(std::vector<MaterialPoint>& mpData, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  for (MaterialPoint& mp : mpData) {
    mp.Fn << 1 + 0.05 * r(gen), 0.05 * r(gen), 0, 0.05 * r(gen), 1 + 0.05 * r(gen), 0, 0, 0, 1;
    mp.epsEn << 1e-3 * r(gen), 1e-3 * r(gen), 1e-3 * r(gen), 1e-3 * r(gen), 0, 0;
  }
}

// random displacement increment on the nodes linked to the points
inline Eigen::VectorXd randomUvw(const Analysis& an, double size, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  Eigen::VectorXd uvw = Eigen::VectorXd::Zero(an.mesh.nDoF());
  for (const MaterialPoint& mp : an.mpData)
    for (int v = 0; v < mp.nn; ++v)
      for (int i = 0; i < nD; ++i) uvw(dof(mp.nIN[v], i)) = size * r(gen);
  return uvw;
}

// relative difference |Kt - Kfd| / |Kt| between the assembled tangent and central
// differences of the assembled internal force, over the columns of the linked dofs
inline double tangentError(Analysis& an, const Eigen::VectorXd& uvw, Formulation form) {
  const Eigen::MatrixXd Kt = Eigen::MatrixXd(detMPs(uvw, an.mpData, form).Kt);
  Eigen::MatrixXd Kfd = Eigen::MatrixXd::Zero(Kt.rows(), Kt.cols());
  const double d = 1e-7;
  for (int c = 0; c < uvw.size(); ++c) {
    if (Kt.col(c).norm() == 0.0) continue;  // dof not linked to any point
    Eigen::VectorXd up = uvw, um = uvw;
    up(c) += d;
    um(c) -= d;
    Kfd.col(c) = (detMPs(up, an.mpData, form).fint - detMPs(um, an.mpData, form).fint) / (2 * d);
  }
  return (Kt - Kfd).norm() / Kt.norm();
}

// the whole text of a file ("" when it does not exist)
inline std::string fileText(const std::string& path) {
  std::ifstream f(path);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

}  // namespace ample::testing
