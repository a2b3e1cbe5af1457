//--------------------------------------------------------------------------
// makeVtkMP — legacy VTK file of the material points of one load step
//--------------------------------------------------------------------------
// [AMPLE] sec 5.2 (fig 13): mpData_<lstp>.vtk, one vertex per point at its
// current position with point data: displacement (vector), Cauchy stress
// sig_xx sig_yy sig_zz sig_xy, von Mises rho = sqrt(2 J2), volume, domain half
// lengths lp. Written to a temporary name, then renamed. ASCII (reals as
// "double", 15 digits) or BINARY (big-endian 4-byte "float" and int;
// makeVtkWriter.h), the same sections and names.
// Inputs:  mpData · path · format
// Outputs: the file at path
// Tests:   tests/test_output.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"
#include "makeVtkWriter.h"
#include <string>

namespace ample {

void makeVtkMP(const std::vector<MaterialPoint>& mpData, const std::string& path,
               VtkFormat format = VtkFormat::Ascii);

}  // namespace ample
