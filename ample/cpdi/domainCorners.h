//--------------------------------------------------------------------------
// domainCorners — the four corners of a material point's domain
//--------------------------------------------------------------------------
// Anticlockwise from the lower-left one. GIMP: the rectangle x_p +- l_p;
// CPDI1: the parallelogram x_p + [-1 1 1 -1] s/2 + [-1 -1 1 1] t/2 ([CPDI]
// sec 2 (iii)); CPDI2: the stored corners; MPM: the point itself, four times.
// Inputs:  mp (mpType, mpC, lp; CPDI: cpdi->st, cpdi->xc)
// Outputs: corners (2 x 4), column c is corner c
// Tests:   tests/test_cpdi.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"

namespace ample {

using Corners = Eigen::Matrix<double, nD, 4>;

Corners domainCorners(const MaterialPoint& mp);
double quadArea(const Corners& x);  // area of the quadrilateral (positive when anticlockwise)

}  // namespace ample
