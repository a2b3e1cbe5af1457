//--------------------------------------------------------------------------
// SvpCPDI — CPDI1 and CPDI2 basis functions and gradients of one node
//--------------------------------------------------------------------------
// [CPDI] sec 2 (iv). Sc(c) is the grid (bi-linear) basis function of the
// node evaluated at domain corner c (anticlockwise from the lower-left).
// CPDI1 (parallelogram spanned by s, t, area V = |s x t|):
//   S  = (Sc1 + Sc2 + Sc3 + Sc4)/4
//   dS = 1/(2V) {(Sc1 - Sc3)[sy - ty; tx - sx] + (Sc2 - Sc4)[sy + ty; -sx - tx]}
// CPDI2 (quadrilateral with corners x1..x4): S = (1/V) int S^ dA, the domain
// average of the bi-linear interpolant S^ of the corner values. With the
// isoparametric map, det J = J0 + J1 xi + J2 eta, V = 4 J0, this gives the
// weights w_c = 1/4 + (J1 xi_c + J2 eta_c)/(12 J0) — derived here, not copied
// from the original CPDI2 paper, whose printed weights were wrong ([Lagrangian],
// footnote 6). The gradient is the domain average of grad S^ (divergence form):
//   dS = 1/(2V) {Sc1 [y2 - y4; x4 - x2] + Sc2 [y3 - y1; x1 - x3]
//               + Sc3 [y4 - y2; x2 - x4] + Sc4 [y1 - y3; x3 - x1]}
// Inputs:  Sc (4) · st (2x2, CPDI1: columns s, t) or x (2x4, CPDI2 corners)
// Outputs: {S, dS (2)}
// Tests:   tests/test_cpdi.cpp
//--------------------------------------------------------------------------
#pragma once
#include "domainCorners.h"

namespace ample {

struct Basis2D {
  double S;     // basis function value
  Vector2d dS;  // gradient with respect to X~ (start of the load step)
};

Basis2D SvpCPDI1(const Eigen::Vector4d& Sc, const Eigen::Matrix2d& st);
Basis2D SvpCPDI2(const Eigen::Vector4d& Sc, const Corners& x);
Eigen::Vector4d cpdi2Weights(const Corners& x);  // the weights w_c of S = sum w_c Sc

}  // namespace ample
