//--------------------------------------------------------------------------
// krylov — preconditioned conjugate gradients and right-preconditioned GMRES
//--------------------------------------------------------------------------
// See krylov.h for when each is used, inputs and outputs.
//--------------------------------------------------------------------------
#include "krylov.h"
#include <cmath>
#include <vector>

namespace ample {

double infNorm(const SpMat& K) {                        // largest row sum of |K|
  Eigen::VectorXd rowSum = Eigen::VectorXd::Zero(K.rows());
  for (int k = 0; k < K.outerSize(); ++k)
    for (SpMat::InnerIterator it(K, k); it; ++it) rowSum(it.row()) += std::abs(it.value());
  return K.rows() ? rowSum.maxCoeff() : 0.0;
}

// backward error from a residual r of x (normK = ||K||_inf)
static double backward(double normK, const Eigen::VectorXd& x, const Eigen::VectorXd& b, double rInf) {
  return rInf / (normK * x.lpNorm<Eigen::Infinity>() + b.lpNorm<Eigen::Infinity>() + 1e-300);
}

double backwardError(const SpMat& K, double normK, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  return backward(normK, x, b, (K * x - b).lpNorm<Eigen::Infinity>());
}

// stop: reached the target, or stagnated (less than halved) once acceptable
static bool done(double be, double bePrev, double target, double accept) {
  return be <= target || (be <= accept && be > 0.5 * bePrev);
}

KrylovResult pcg(const SpMat& K, const Preconditioner& M, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                 int maxIt, double target, double accept) {
  const double normK = infNorm(K);
  KrylovResult out;
  x = Eigen::VectorXd::Zero(b.size());
  Eigen::VectorXd r = b, z = M(r), p = z;               // residual, preconditioned residual, direction
  double rz = r.dot(z), be = 1.0;
  while (out.iterations < maxIt && b.lpNorm<Eigen::Infinity>() > 0.0) {
    const Eigen::VectorXd Kp = K * p;
    const double pKp = p.dot(Kp);
    if (!(pKp > 0.0)) break;                            // K or M not positive definite
    const double alpha = rz / pKp;
    x += alpha * p;
    r -= alpha * Kp;
    out.iterations++;
    const double bePrev = be;
    be = backward(normK, x, b, r.lpNorm<Eigen::Infinity>());
    if (done(be, bePrev, target, accept)) break;
    z = M(r);
    const double rzNew = r.dot(z);
    p = z + (rzNew / rz) * p;
    rz = rzNew;
  }
  out.backwardError = backward(normK, x, b, (b - K * x).lpNorm<Eigen::Infinity>());  // the true one
  out.converged = x.allFinite() && out.backwardError <= accept;
  return out;
}

KrylovResult gmres(const SpMat& K, const Preconditioner& M, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                   int maxIt, double target, double accept, int restart) {
  const double normK = infNorm(K);
  KrylovResult out;
  x = Eigen::VectorXd::Zero(b.size());
  double be = backward(normK, x, b, b.lpNorm<Eigen::Infinity>());
  while (out.iterations < maxIt && !(be <= target)) {   // one restart cycle from x0 = x
    const Eigen::VectorXd x0 = x, r0 = b - K * x0;
    const double beta = r0.norm();
    if (beta == 0.0) break;
    std::vector<Eigen::VectorXd> V{r0 / beta}, Z;       // Arnoldi basis; Z = M^-1 V (x = x0 + Z y)
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(restart + 1, restart);  // Hessenberg, rotated to R
    Eigen::VectorXd g = Eigen::VectorXd::Zero(restart + 1), c(restart), s(restart);
    g(0) = beta;                                        // rotated beta e1: |g(j+1)| = ||r||_2
    bool stop = false;
    for (int j = 0; j < restart && out.iterations < maxIt && !stop; ++j) {
      Z.push_back(M(V[j]));
      Eigen::VectorXd w = K * Z[j];
      out.iterations++;
      for (int i = 0; i <= j; ++i) {                    // modified Gram-Schmidt
        H(i, j) = V[i].dot(w);
        w -= H(i, j) * V[i];
      }
      H(j + 1, j) = w.norm();
      V.push_back(w / (H(j + 1, j) + 1e-300));
      for (int i = 0; i < j; ++i) {                     // earlier Givens rotations on column j
        const double t = c(i) * H(i, j) + s(i) * H(i + 1, j);
        H(i + 1, j) = -s(i) * H(i, j) + c(i) * H(i + 1, j);
        H(i, j) = t;
      }
      const double h = std::hypot(H(j, j), H(j + 1, j));  // new rotation zeroes H(j+1,j)
      c(j) = H(j, j) / h;
      s(j) = H(j + 1, j) / h;
      H(j, j) = h;
      H(j + 1, j) = 0.0;
      g(j + 1) = -s(j) * g(j);
      g(j) = c(j) * g(j);
      const Eigen::VectorXd y =                         // least squares: R y = g
          H.topLeftCorner(j + 1, j + 1).triangularView<Eigen::Upper>().solve(g.head(j + 1));
      x = x0;
      for (int i = 0; i <= j; ++i) x += y(i) * Z[i];
      const double bePrev = be;                         // ||r||_2 >= ||r||_inf: an upper bound
      be = backward(normK, x, b, std::abs(g(j + 1)));
      stop = done(be, bePrev, target, accept);
    }
    if (stop) break;
  }
  out.backwardError = backward(normK, x, b, (b - K * x).lpNorm<Eigen::Infinity>());  // the true one
  out.converged = x.allFinite() && out.backwardError <= accept;
  return out;
}

}  // namespace ample
