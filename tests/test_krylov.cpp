// Tests of the Krylov solves of solver=KRYLOV (ample/solver/krylov.h) and of linSolve with
// solver=KRYLOV: PCG on a symmetric positive definite matrix and right-preconditioned GMRES
// on an unsymmetric one against a dense LU solve (Eigen's PartialPivLU, not the code under
// test); an exact preconditioner converges in 1 iteration, a perturbed one in a few, a bad one
// spends the iterations allowed; the backward error against its definition on a hand case;
// linSolve's counters: one factorisation a load step, a refactorisation when Kt(fd,fd) changes
// too much for the held factor, without a Krylov try after a solve that needed more than
// half the iterations allowed, and a direct solve where the Krylov one leaves a residual over
// 1e-3 of the load (a nearly singular Kt).
#include "ample/linSolve.h"
#include "ample/solver/chosenSolve.h"
#include "ample/solver/krylov.h"
#include <doctest/doctest.h>
#include <Eigen/Dense>
#include <cmath>

using namespace ample;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {
// a 1D Laplacian (2 on the diagonal, -1 beside) plus shift on the diagonal and, when
// unsym != 0, unsym added above the diagonal only: SPD for unsym = 0
SpMat tridiagonal(int n, double shift, double unsym) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0 + shift);
    if (i + 1 < n) t.emplace_back(i, i + 1, -1.0 + unsym), t.emplace_back(i + 1, i, -1.0);
  }
  SpMat K(n, n);
  K.setFromTriplets(t.begin(), t.end());
  return K;
}
VectorXd load(int n) {
  VectorXd b(n);
  for (int i = 0; i < n; ++i) b(i) = std::cos(0.3 * i) + 0.1 * i;
  return b;
}
// every one of n dofs free; a FreeSystem for solver=KRYLOV
std::vector<int> allFree(int n) {
  std::vector<int> fd(n);
  for (int i = 0; i < n; ++i) fd[i] = i;
  return fd;
}
struct KrylovSystem : FreeSystem {
  KrylovSystem() { choice = LinearSolver::KRYLOV; }
};
// M = (K of another shift)^-1 by a dense LU: exact when shift is K's own
Preconditioner inverseOf(const SpMat& P) {
  const Eigen::PartialPivLU<MatrixXd> lu{MatrixXd(P)};
  return [lu](const VectorXd& r) { return VectorXd(lu.solve(r)); };
}
}  // namespace

TEST_SUITE("krylov") {
  TEST_CASE("krylov: the backward error of a 2 x 2 system by hand") {
    SpMat K(2, 2);
    K.insert(0, 0) = 2, K.insert(0, 1) = -1, K.insert(1, 1) = 3;   // row sums 3 and 3: ||K|| = 3
    VectorXd x(2), b(2);
    x << 1, 1;                                                     // K x = (1, 3)
    b << 1, 2;                                                     // residual (0, 1)
    CHECK(infNorm(K) == doctest::Approx(3.0));
    CHECK(backwardError(K, infNorm(K), x, b) == doctest::Approx(1.0 / (3.0 * 1 + 2)));
  }
  TEST_CASE("krylov: PCG with the exact inverse converges in 1 iteration; with a perturbed one in a few") {
    const int n = 40;
    const SpMat K = tridiagonal(n, 0.01, 0.0);
    const VectorXd b = load(n), ref = MatrixXd(K).partialPivLu().solve(b);
    VectorXd x = VectorXd::Zero(n);
    const KrylovResult exact = pcg(K, inverseOf(K), b, x, 30, 1e-14);
    CHECK(exact.iterations == 1);
    CHECK(exact.converged);
    CHECK((x - ref).norm() <= 1e-10 * ref.norm());
    x.setZero();
    const KrylovResult near = pcg(K, inverseOf(tridiagonal(n, 0.02, 0.0)), b, x, 30, 1e-14);
    MESSAGE("PCG, preconditioner of a diagonal 1% off: ", near.iterations, " iterations");
    CHECK(near.converged);
    CHECK(near.iterations > 1);
    CHECK(near.iterations <= 10);
    CHECK((x - ref).norm() <= 1e-10 * ref.norm());
    CHECK(near.backwardError <= 1e-14);
  }
  TEST_CASE("krylov: GMRES with the exact inverse converges in 1 iteration; with a perturbed one in a few") {
    const int n = 40;
    const SpMat K = tridiagonal(n, 0.01, 0.4);                    // unsymmetric
    const VectorXd b = load(n), ref = MatrixXd(K).partialPivLu().solve(b);
    VectorXd x = VectorXd::Zero(n);
    const KrylovResult exact = gmres(K, inverseOf(K), b, x, 30, 1e-14);
    CHECK(exact.iterations == 1);
    CHECK(exact.converged);
    CHECK((x - ref).norm() <= 1e-10 * ref.norm());
    x.setZero();
    const KrylovResult near = gmres(K, inverseOf(tridiagonal(n, 0.02, 0.38)), b, x, 30, 1e-14);
    MESSAGE("GMRES, preconditioner of a matrix ~1% off: ", near.iterations, " iterations");
    CHECK(near.converged);
    CHECK(near.iterations > 1);
    CHECK(near.iterations <= 10);
    CHECK((x - ref).norm() <= 1e-10 * ref.norm());
    CHECK(near.backwardError <= 1e-14);
  }
  TEST_CASE("krylov: a bad preconditioner spends the iterations allowed without convergence") {
    const int n = 200;
    const SpMat K = tridiagonal(n, 1e-4, 0.0);                    // condition ~ 4e4
    const VectorXd b = load(n);
    const Preconditioner identity = [](const VectorXd& r) { return r; };
    VectorXd x = VectorXd::Zero(n);
    const KrylovResult p = pcg(K, identity, b, x, 5, 1e-14);
    CHECK(!p.converged);
    CHECK(p.iterations == 5);
    x.setZero();
    const KrylovResult g = gmres(K, identity, b, x, 5, 1e-14);
    CHECK(!g.converged);
    CHECK(g.iterations == 5);
  }
  TEST_CASE("krylov: linSolve with solver=KRYLOV factorises once a load step and solves later passes by PCG") {
    const int n = 30;
    const std::vector<int> fd = allFree(n);
    const VectorXd b = load(n);
    KrylovSystem S;
    const LinSolveOut first = chosenSolve(S, {}, tridiagonal(n, 0.01, 0.0), b, 1, fd);
    CHECK(S.factorisations == 1);
    CHECK(S.krylovSolves == 0);
    const SpMat K2 = tridiagonal(n, 0.012, 0.0);                  // the next pass: Kt changed a little
    const LinSolveOut second = chosenSolve(S, {}, K2, b, 2, fd);
    const VectorXd ref = MatrixXd(K2).partialPivLu().solve(b);
    CHECK((second.duvw - ref).norm() <= 1e-10 * ref.norm());
    CHECK(S.factorisations == 1);                                 // no new factorisation
    CHECK(S.krylovSolves == 1);
    CHECK(S.krylovIterations >= 2);
    CHECK(S.krylovIterations <= 10);
    chosenSolve(S, {}, K2, b, 1, fd);                               // a new load step: factorised again
    CHECK(S.factorisations == 2);
    CHECK(S.krylovSolves == 1);
    CHECK((first.duvw - MatrixXd(tridiagonal(n, 0.01, 0.0)).partialPivLu().solve(b)).norm() <= 1e-10 * ref.norm());
  }
  TEST_CASE("krylov: linSolve with solver=KRYLOV refactorises when the held factor is too far off") {
    const int n = 200;
    const std::vector<int> fd = allFree(n);
    const VectorXd b = load(n);
    KrylovSystem S;
    S.krylovMaxIt = 3;
    chosenSolve(S, {}, tridiagonal(n, 1e-4, 0.0), b, 1, fd);
    const SpMat far = tridiagonal(n, 1.0, 0.0);                   // a very different pass
    const LinSolveOut x = chosenSolve(S, {}, far, b, 2, fd);
    CHECK(S.krylovSolves == 1);
    CHECK(S.krylovIterations == 3);                               // spent, then refactorised
    CHECK(S.factorisations == 2);
    const VectorXd ref = MatrixXd(far).partialPivLu().solve(b);
    CHECK((x.duvw - ref).norm() <= 1e-12 * ref.norm());
    chosenSolve(S, {}, far, b, 3, fd);                              // the new factor is exact: 1 iteration
    CHECK(S.factorisations == 2);
    CHECK(S.krylovIterations == 4);
  }
  TEST_CASE("krylov: linSolve with solver=KRYLOV on an unsymmetric Kt uses SparseLU and GMRES") {
    const int n = 30;
    const std::vector<int> fd = allFree(n);
    const VectorXd b = load(n);
    KrylovSystem S;
    chosenSolve(S, {}, tridiagonal(n, 0.01, 0.3), b, 1, fd);
    CHECK(!S.factorSymmetric);
    const SpMat K2 = tridiagonal(n, 0.012, 0.31);
    const LinSolveOut x = chosenSolve(S, {}, K2, b, 2, fd);
    const VectorXd ref = MatrixXd(K2).partialPivLu().solve(b);
    CHECK((x.duvw - ref).norm() <= 1e-10 * ref.norm());
    CHECK(S.factorisations == 1);
    CHECK(S.krylovSolves == 1);
    CHECK(S.krylovIterations >= 2);
  }
  TEST_CASE("krylov: after a Krylov solve that needed more than half the iterations allowed, the next pass refactorises") {
    const int n = 200;
    const std::vector<int> fd = allFree(n);
    const VectorXd b = load(n);
    KrylovSystem S;
    S.krylovMaxIt = 30;
    chosenSolve(S, {}, tridiagonal(n, 1e-4, 0.0), b, 1, fd);       // the step's factor
    const SpMat drifted = tridiagonal(n, 0.01, 0.0);
    const LinSolveOut x = chosenSolve(S, {}, drifted, b, 2, fd);   // solved by PCG, slowly (20 iterations)
    REQUIRE(S.krylovSolves == 1);
    CHECK(S.krylovIterations > 15);                                // more than half of 30 ...
    CHECK(S.krylovIterations <= 30);                               // ... and converged
    CHECK(S.factorisations == 1);
    const VectorXd ref = MatrixXd(drifted).partialPivLu().solve(b);
    CHECK((x.duvw - ref).norm() <= 1e-10 * ref.norm());
    chosenSolve(S, {}, drifted, b, 3, fd);                           // no Krylov try: factorised
    CHECK(S.krylovSolves == 1);
    CHECK(S.factorisations == 2);
    chosenSolve(S, {}, drifted, b, 4, fd);                           // the new factor is exact: PCG again
    CHECK(S.krylovSolves == 2);
    CHECK(S.factorisations == 2);
    KrylovSystem T;                                                // a small drift: 13 iterations
    chosenSolve(T, {}, tridiagonal(n, 1e-4, 0.0), b, 1, fd);
    chosenSolve(T, {}, tridiagonal(n, 0.002, 0.0), b, 2, fd);
    REQUIRE(T.krylovIterations <= 15);
    chosenSolve(T, {}, tridiagonal(n, 0.002, 0.0), b, 3, fd);       // tried by PCG again
    CHECK(T.krylovSolves == 2);
    CHECK(T.factorisations == 1);
  }
  TEST_CASE("krylov: a Krylov solve with a small backward error but a residual over 1e-3 of the load is solved directly") {
    const int n = 30;                                             // K nearly singular: its lowest
    const std::vector<int> fd = allFree(n);                       // eigenvalue 4e-13, so x is huge and
    const VectorXd b = load(n);                                   // ||K x - b|| = 1e-14 ||K|| ||x|| is
    KrylovSystem S;                                               // not small against ||b||
    chosenSolve(S, {}, tridiagonal(n, 0.01, 0.0), b, 1, fd);
    const double lowest = 2 - 2 * std::cos(M_PI / (n + 1));       // the 1D Laplacian's, analytic
    const SpMat K = tridiagonal(n, -lowest + 4e-13, 0.0);
    LinSolveOut x;
    REQUIRE_NOTHROW(x = chosenSolve(S, {}, K, b, 2, fd));           // (Krylov's alone: "singular")
    CHECK(S.krylovSolves == 1);                                   // tried, then refactorised
    CHECK(S.factorisations == 2);
    CHECK((K * x.duvw - b).norm() <= 1e-3 * b.norm());
  }
}
