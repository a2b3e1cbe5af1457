//--------------------------------------------------------------------------
// formPCstiff — consistent tangent of the previously converged formulation
//--------------------------------------------------------------------------
// [Lagrangian] eqs A.3-A.6. See formPCstiff.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "formPCstiff.h"

namespace ample {

Matrix9d formPCstiff(const Matrix3d& dF, double Jn, const Matrix6d& D, const Matrix3d& tau,
                     const Matrix3d& bEn, const Matrix3d& BeT) {
  constexpr int voigt[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};
  const Matrix3d bFt = bEn * dF.transpose(), Fb = dF * bEn, iF = dF.inverse();
  Eigen::Matrix<double, 6, 9> P = Eigen::Matrix<double, 6, 9>::Zero();  // tensor ij -> Voigt row
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) P(voigt[i][j], 3 * i + j) = 1.0;
  const Matrix9d D9 = P.transpose() * D * P;                                           // D_ijkl
  Matrix9d Bt;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          Bt(3 * i + j, 3 * k + l) = (i == k ? bFt(l, j) : 0.0) + (j == k ? Fb(i, l) : 0.0);  // A.5
  const Matrix9d T = 0.5 * D9 * dLogdB(BeT) * Bt;                                       // A.4
  Matrix9d A = Matrix9d::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) {
          double a = 0.0;
          for (int m = 0; m < 3; ++m)
            a += T(3 * i + m, 3 * k + l) * iF(j, m) - tau(i, m) * iF(j, k) * iF(l, m);  // A.3, A.6
          A(3 * i + j, 3 * k + l) = a / Jn;
        }
  return A;
}

Matrix4d formPCstiff2D(const Matrix3d& dF, double Jn, const Matrix6d& D, const Matrix3d& tau,
                       const Matrix3d& bEn, const Matrix3d& BeT) {
  const Matrix3d bFt = bEn * dF.transpose(), Fb = dF * bEn, iF = dF.inverse();
  Matrix4d Bt;
  for (int p = 0; p < 4; ++p)
    for (int q = 0; q < 4; ++q) {
      const int r = p / 2, s = p % 2, k = q / 2, l = q % 2;
      Bt(p, q) = (r == k ? bFt(l, s) : 0.0) + (s == k ? Fb(r, l) : 0.0);            // A.5
    }
  const Matrix4d T = 0.5 * elasticBlock2D(D) * dLogdB2D(BeT) * Bt;                   // A.4
  Matrix4d A;
  for (int p = 0; p < 4; ++p)
    for (int q = 0; q < 4; ++q) {
      const int i = p / 2, j = p % 2, k = q / 2, l = q % 2;
      double a = 0.0;
      for (int m = 0; m < 2; ++m)
        a += T(2 * i + m, q) * iF(j, m) - tau(i, m) * iF(j, k) * iF(l, m);          // A.3, A.6
      A(p, q) = a / Jn;
    }
  return A;
}

}  // namespace ample
