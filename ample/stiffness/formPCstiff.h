//--------------------------------------------------------------------------
// formPCstiff — consistent tangent of the previously converged formulation
//--------------------------------------------------------------------------
// [Lagrangian] appendix A.2, eqs A.3-A.6, with P~ = tau dF^-T / Jn (eq 18):
//   A~_ijkl = (1/Jn) [ dtau_im/d dF_kl (dF^-1)_jm - tau_im (dF^-1)_jk (dF^-1)_lm ]
//   dtau_im/d dF_kl = 1/2 D_imop L_oprs B~_rskl                      (A.4)
//   B~_rskl = delta_rk (b_e,n dF')_ls + (dF b_e,n)_rl delta_sk        (A.5)
// with L = d ln(b)/db at the trial b_e (formULstiff.h). Tensors are 9x9
// matrices indexed by pairs (i,j) -> 3*i + j.
// Inputs:  dF (3x3) increment of the step · Jn = det(Fn) · D (6x6) ·
//          tau (3x3) Kirchhoff stress · bEn (3x3) b_e at the start of the step ·
//          BeT (3x3) trial b_e
// Outputs: A (9x9) with delta P~_ij = A(3i+j, 3k+l) delta dF_kl
// Tests:   tests/test_detMPs.cpp (finite differences of the PC internal force)
//--------------------------------------------------------------------------
#pragma once
#include "formULstiff.h"

namespace ample {

Matrix9d formPCstiff(const Matrix3d& dF, double Jn, const Matrix6d& D, const Matrix3d& tau,
                     const Matrix3d& bEn, const Matrix3d& BeT);

// plane strain: the in-plane block from 4x4 blocks, pairs (i,j) -> 2*i + j
// (as formULstiff2D; exact because dF, b_e and tau are block diagonal)
Matrix4d formPCstiff2D(const Matrix3d& dF, double Jn, const Matrix6d& D, const Matrix3d& tau,
                       const Matrix3d& bEn, const Matrix3d& BeT);

}  // namespace ample
