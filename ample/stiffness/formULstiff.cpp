//--------------------------------------------------------------------------
// formULstiff — spatial consistent tangent a_ijkl of the updated Lagrangian form
//--------------------------------------------------------------------------
// [Lagrangian] eqs A.1-A.2. See formULstiff.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "formULstiff.h"
#include "constitutive/exercise.h"
#include <Eigen/Eigenvalues>
#include <cmath>

namespace ample {

namespace {
constexpr int voigt[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};  // (i,j) -> Voigt row

// (ln a - ln b)/(a - b), written to stay accurate as a -> b (limit 1/b)
double logDividedDifference(double a, double b) {
  const double x = (a - b) / b;
  if (std::abs(x) < 1e-12) return (1.0 - 0.5 * x) / b;
  return std::log1p(x) / (a - b);
}
}  // namespace

Matrix9d dLogdB(const Matrix3d& b) {
  return dLogdB(Eigen::SelfAdjointEigenSolver<Matrix3d>(b));
}

Matrix9d dLogdB(const Eigen::SelfAdjointEigenSolver<Matrix3d>& es) {
  const Vector3d lam = es.eigenvalues();
  const Matrix3d& n = es.eigenvectors();  // column a is eigenvector n_a
  Matrix9d L = Matrix9d::Zero();
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c) {         // L += theta_ac m m', m_(3i+j) = (n_a)_i (n_c)_j
      Eigen::Matrix<double, 9, 1> m;
      for (int i = 0; i < 3; ++i) m.segment<3>(3 * i) = n(i, a) * n.col(c);
      L.noalias() += logDividedDifference(lam(a), lam(c)) * m * m.transpose();
    }
  return L;
}

Matrix9d formULstiff(const Matrix3d& F, const Matrix6d& D, const Vector6d& sig,
                     const Matrix3d& BeT) {
  // BEGIN EXERCISE formULstiff
  Matrix9d D9, B9, S9 = Matrix9d::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) {
          D9(3 * i + j, 3 * k + l) = D(voigt[i][j], voigt[k][l]);
          B9(3 * i + j, 3 * k + l) = (i == k ? BeT(j, l) : 0.0) + (j == k ? BeT(i, l) : 0.0);
          if (j == k) S9(3 * i + j, 3 * k + l) = sig(voigt[i][l]);  // sigma_il delta_jk
        }
  const double J = F.determinant();
  return (0.5 / J) * (D9.lazyProduct(dLogdB(BeT))).lazyProduct(B9) - S9;
  // END EXERCISE
}

Matrix4d dLogdB2D(const Matrix3d& b) { return dLogdB2D(inPlaneEigen(b)); }

Matrix4d dLogdB2D(const InPlaneEigen& b) {
  const Eigen::Vector2d& lam = b.lam;
  const Eigen::Matrix2d& n = b.n;
  Matrix4d L = Matrix4d::Zero();
  for (int a = 0; a < 2; ++a)
    for (int c = 0; c < 2; ++c) {
      Eigen::Vector4d m;
      m << n(0, a) * n.col(c), n(1, a) * n.col(c);
      L.noalias() += logDividedDifference(lam(a), lam(c)) * m * m.transpose();
    }
  return L;
}

Matrix4d elasticBlock2D(const Matrix6d& D) {
  Matrix4d D4;
  for (int p = 0; p < 4; ++p)
    for (int q = 0; q < 4; ++q) D4(p, q) = D(voigt[p / 2][p % 2], voigt[q / 2][q % 2]);
  return D4;
}

Matrix4d formULstiff2D(const Matrix3d& F, const Matrix6d& D, const Vector6d& sig,
                       const Matrix3d& BeT) {
  return formULstiff2D(F, D, sig, BeT, dLogdB2D(BeT));  // L: in-plane block of d ln(b)/db
}

Matrix4d formULstiff2D(const Matrix3d& F, const Matrix6d& D, const Vector6d& sig,
                       const Matrix3d& BeT, const Matrix4d& L) {
  // BEGIN EXERCISE formULstiff
  const Matrix4d D4 = elasticBlock2D(D);
  Matrix4d B4, S4 = Matrix4d::Zero();
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k)
        for (int l = 0; l < 2; ++l) {
          B4(2 * i + j, 2 * k + l) = (i == k ? BeT(j, l) : 0.0) + (j == k ? BeT(i, l) : 0.0);
          if (j == k) S4(2 * i + j, 2 * k + l) = sig(voigt[i][l]);
        }
  return (0.5 / F.determinant()) * D4 * L * B4 - S4;
  // END EXERCISE
}

}  // namespace ample
