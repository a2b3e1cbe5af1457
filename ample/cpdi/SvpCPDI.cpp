//--------------------------------------------------------------------------
// SvpCPDI — CPDI1 and CPDI2 basis functions and gradients of one node
//--------------------------------------------------------------------------
// [CPDI] sec 2 (iv). See SvpCPDI.h for the formulas, inputs and outputs.
//--------------------------------------------------------------------------
#include "SvpCPDI.h"
#include "constitutive/exercise.h"
#include <cmath>

namespace ample {

Basis2D SvpCPDI1(const Eigen::Vector4d& Sc, const Eigen::Matrix2d& st) {
  const Vector2d s = st.col(0), t = st.col(1);
  const double V = std::abs(s(0) * t(1) - s(1) * t(0));
  const Vector2d g = ((Sc(0) - Sc(2)) * Vector2d(s(1) - t(1), t(0) - s(0)) +
                      (Sc(1) - Sc(3)) * Vector2d(s(1) + t(1), -s(0) - t(0))) / (2.0 * V);
  return {Sc.mean(), g};
}

Eigen::Vector4d cpdi2Weights(const Corners& x) {
  // BEGIN EXERCISE SvpCPDI2
  const double xi[4] = {-1, 1, 1, -1}, eta[4] = {-1, -1, 1, 1};
  auto detJ = [&](double r, double s) {  // det of the isoparametric Jacobian at (r, s)
    Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
    for (int c = 0; c < 4; ++c) {
      J.col(0) += 0.25 * xi[c] * (1 + eta[c] * s) * x.col(c);   // dx/dxi
      J.col(1) += 0.25 * eta[c] * (1 + xi[c] * r) * x.col(c);   // dx/deta
    }
    return J.determinant();
  };
  const double J0 = detJ(0, 0), J1 = 0.5 * (detJ(1, 0) - detJ(-1, 0)),
               J2 = 0.5 * (detJ(0, 1) - detJ(0, -1));          // det J is linear in xi, eta
  Eigen::Vector4d w;
  for (int c = 0; c < 4; ++c) w(c) = 0.25 + (J1 * xi[c] + J2 * eta[c]) / (12.0 * J0);
  return w;
  // END EXERCISE
}

Basis2D SvpCPDI2(const Eigen::Vector4d& Sc, const Corners& x) {
  const double V = quadArea(x);
  Vector2d g = Vector2d::Zero();
  for (int c = 0; c < 4; ++c) {
    const Vector2d& next = x.col((c + 1) % 4);
    const Vector2d& prev = x.col((c + 3) % 4);
    g += Sc(c) * Vector2d(next(1) - prev(1), prev(0) - next(0));
  }
  return {cpdi2Weights(x).dot(Sc), g / (2.0 * V)};
}

}  // namespace ample
