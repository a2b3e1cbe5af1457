// Tests of linSolve ([AMPLE] eq 29): skipped at NRit 0, prescribed
// increments at NRit 1 only, equilibrium of the free dofs, reactions, dofs
// that are neither free nor prescribed left at zero, a singular system refused;
// each solver= of the build (solverChoice.h) against SparseLU, and the refusal of
// the ones the build lacks (docs/scaling.md, "The sparse solve").
#include "ample/errors.h"
#include "ample/detFDoFs.h"
#include "ample/remedies/loneNodes.h"
#include "ample/linSolve.h"
#include "ample/solver/chosenSolve.h"
#include "ample/solver/solverChoice.h"
#include "testProblems.h"
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>
#include <sys/wait.h>

using namespace ample;

namespace {
// a chain of 4 springs between 5 dofs, spring i (dofs i, i+1) of stiffness i + 1;
// symmetric positive semi-definite (one rigid-body mode) until a dof is held
SpMat chain() {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < 4; ++i) {
    const double k = i + 1.0;
    t.emplace_back(i, i, k);
    t.emplace_back(i + 1, i + 1, k);
    t.emplace_back(i, i + 1, -k);
    t.emplace_back(i + 1, i, -k);
  }
  SpMat K(5, 5);
  K.setFromTriplets(t.begin(), t.end());
  return K;
}

// the solver= choices of this build but LU, and the ones it lacks
std::vector<LinearSolver> solvers(bool builtOnes) {
  std::vector<LinearSolver> v;
  for (size_t k = 1; k < solverNames().size(); ++k)
    if (solverBuilt(LinearSolver(k)) == builtOnes) v.push_back(LinearSolver(k));
  return v;
}
bool everySolverBuilt() { return solvers(false).empty(); }

// Kt and fd of load step 1 of the collapse (a = 2: h = 1 m, 3 x 3 points per cell; uvw = 0,
// the elastic tangent), as loadStep builds them before its first linSolve
struct CollapseStep1 {
  SpMat Kt;
  std::vector<int> fd;
};
CollapseStep1 collapseStep1() {
  const Setup* s = findSetup("collapse");
  REQUIRE(s != nullptr);
  Params P = s->params();
  Analysis an = s->setupGrid(P);
  const int nDoF = an.mesh.nDoF();
  elemMPinfo(an.mesh, an.mpData);
  CollapseStep1 c{SpMat(), detFDoFsLone(an.mesh, an.mpData)};
  DetMPsOut mps;
  mps.Kt = stiffnessPattern(nDoF, an.mpData);
  pointLoopOf(an.formulation)(Eigen::VectorXd::Zero(nDoF), an.mpData, an.formulation, mps);
  c.Kt = mps.Kt;
  return c;
}
}  // namespace

TEST_SUITE("linSolve") {
  TEST_CASE("linSolve: zero increments at NRit = 0 (that pass only builds Kt)") {
    const LinSolveOut o = linSolve({{0, 0.5}}, chain(), Eigen::VectorXd::Ones(5), 0, {1, 2, 3, 4});
    REQUIRE(o.duvw.size() == 5);
    REQUIRE(o.drct.size() == 5);
    CHECK(o.duvw.norm() == 0.0);
    CHECK(o.drct.norm() == 0.0);
    // the same call at NRit = 1 does move: the prescribed 0.5 enters
    CHECK(linSolve({{0, 0.5}}, chain(), Eigen::VectorXd::Ones(5), 1, {1, 2, 3, 4}).duvw(0) == 0.5);
  }
  TEST_CASE("linSolve: at NRit = 1 the prescribed increment enters / Kff x = rhs / reactions") {
    const SpMat K = chain();
    Eigen::VectorXd oobf(5);
    oobf << 0.7, 0.5, -1.0, 0.25, 2.0;  // out-of-balance force
    const std::vector<BC> bc = {{0, 0.1}};
    const std::vector<int> fd = {1, 2, 3, 4};
    const LinSolveOut o = linSolve(bc, K, oobf, 1, fd);
    CHECK(o.duvw(0) == 0.1);
    const Eigen::VectorXd r = K * o.duvw - oobf;  // Kff x + Kfb u_b = oobf_f
    for (int d : fd) CHECK(std::abs(r(d)) <= 1e-13);
    CHECK(std::abs(o.drct(0) - r(0)) <= 1e-13);  // drct(bc) = Kt(bc,:) duvw - oobf(bc)
    for (int d : fd) CHECK(o.drct(d) == 0.0);     // reactions only at the prescribed dofs
    // analytic: the reaction balances the applied forces, and spring i carries
    // the force applied beyond it, so it stretches by (sum_{j>i} oobf_j) / k_i
    CHECK(o.drct(0) == doctest::Approx(-(oobf.sum())).epsilon(1e-13));
    double u = 0.1;
    for (int i = 0; i < 4; ++i) {
      u += oobf.tail(4 - i).sum() / (i + 1.0);
      CHECK(o.duvw(i + 1) == doctest::Approx(u).epsilon(1e-13));
    }
  }
  TEST_CASE("linSolve: at NRit = 2 the prescribed increment is zero") {
    const SpMat K = chain();
    Eigen::VectorXd oobf = Eigen::VectorXd::Zero(5);
    oobf(4) = 2.0;
    const LinSolveOut o = linSolve({{0, 0.1}}, K, oobf, 2, {1, 2, 3, 4});
    CHECK(o.duvw(0) == 0.0);
    CHECK(o.duvw(4) == doctest::Approx(2.0 * (1 + 1 / 2. + 1 / 3. + 1 / 4.)).epsilon(1e-13));
    CHECK(o.drct(0) == doctest::Approx(-2.0).epsilon(1e-13));
    CHECK(linSolve({{0, 0.1}}, K, Eigen::VectorXd::Zero(5), 2, {1, 2, 3, 4}).duvw.norm() == 0.0);
  }
  TEST_CASE("linSolve: a prescribed dof inside the chain / dofs not in fd stay zero") {
    const SpMat K = chain();
    Eigen::VectorXd oobf = Eigen::VectorXd::Zero(5);
    oobf(4) = 1.0;  // dof 4 is inactive (not in fd, no bc): its force is ignored
    oobf(0) = -3.0;
    const LinSolveOut o = linSolve({{2, -0.2}}, K, oobf, 1, {0, 1, 3});
    CHECK(o.duvw(2) == -0.2);
    CHECK(o.duvw(4) == 0.0);
    CHECK(o.drct(4) == 0.0);
    const Eigen::VectorXd r = K * o.duvw - oobf;
    for (int d : {0, 1, 3}) CHECK(std::abs(r(d)) <= 1e-13);
    // analytic: springs 0 and 1 (k = 1, 2) in series carry -3 to dof 2; spring 2
    // (k = 3) ties dof 3 to dof 2 with dof 4 held at 0 by spring 3 (k = 4)
    CHECK(o.duvw(0) == doctest::Approx(-0.2 - 3.0 * (1.0 + 0.5)).epsilon(1e-13));
    CHECK(o.duvw(3) == doctest::Approx(-0.2 * 3.0 / 7.0).epsilon(1e-13));
    CHECK(std::abs(o.drct(2) - r(2)) <= 1e-13);
  }
  TEST_CASE("linSolve: a singular Kff (rigid-body mode / no constraint) throws RunError") {
    CHECK_THROWS_AS(linSolve({}, chain(), Eigen::VectorXd::Ones(5), 1, {0, 1, 2, 3, 4}), RunError);
  }
  // the acceptance of a symmetric factorisation's solve (chosenSolve.h) against its definition
  TEST_CASE("linSolve: the backward error of a 2 x 2 system by hand") {
    SpMat K(2, 2);
    K.insert(0, 0) = 2, K.insert(0, 1) = -1, K.insert(1, 1) = 3;   // row sums 3 and 3: ||K|| = 3
    Eigen::VectorXd x(2), b(2);
    x << 1, 1;                                                     // K x = (1, 3)
    b << 1, 2;                                                     // residual (0, 1)
    CHECK(backwardError(K, x, b) == doctest::Approx(1.0 / (3.0 * 1 + 2)));
    CHECK(backwardError(K, x, K * x) == 0.0);
  }
  // the chain's analytic solution (above) with solver=LDLT; an unsymmetric chain (a
  // one-way coupling added) has no LDLT: LU solves it, counted as a fallback
  TEST_CASE("linSolve: solver=LDLT solves the symmetric chain as LU does; an unsymmetric Kff falls back to LU") {
    Eigen::VectorXd oobf(5);
    oobf << 0.7, 0.5, -1.0, 0.25, 2.0;
    FreeSystem lu, ldlt;
    ldlt.choice = LinearSolver::LDLT;
    const LinSolveOut a = chosenSolve(lu, {{0, 0.1}}, chain(), oobf, 1, {1, 2, 3, 4});
    const LinSolveOut b = chosenSolve(ldlt, {{0, 0.1}}, chain(), oobf, 1, {1, 2, 3, 4});
    CHECK((a.duvw - b.duvw).norm() <= 1e-14 * a.duvw.norm());
    CHECK(ldlt.fallbacks == 0);
    CHECK(ldlt.notes.empty());
    SpMat K = chain();
    K.coeffRef(2, 3) += 0.5;  // same pattern, no longer symmetric
    const LinSolveOut c = chosenSolve(ldlt, {{0, 0.1}}, K, oobf, 1, {1, 2, 3, 4});
    const Eigen::VectorXd r = K * c.duvw - oobf;
    for (int d = 1; d < 5; ++d) CHECK(std::abs(r(d)) <= 1e-13);
    CHECK(ldlt.fallbacks == 1);
    CHECK(ldlt.builds == 1);  // the same pattern: the analysis kept
    // said once, kept for the run's end (ample prints it after a stop's reason)
    CHECK(ldlt.notes.find("solver=LDLT: Kt(fd,fd) not symmetric to 1e-12") != std::string::npos);
    const std::string once = ldlt.notes;
    chosenSolve(ldlt, {{0, 0.1}}, K, oobf, 1, {1, 2, 3, 4});
    CHECK(ldlt.fallbacks == 2);
    CHECK(ldlt.notes == once);
  }
  // an entry without a mirror across the diagonal (above or below it) makes Kff unsymmetric:
  // SparseLU solves the pass at once, with no LDL^T factorisation tried first
  TEST_CASE("linSolve: solver=LDLT: an entry with no mirror across the diagonal, above or below, goes to SparseLU without an LDL^T try") {
    Eigen::VectorXd oobf(5);
    oobf << 0.7, 0.5, -1.0, 0.25, 2.0;
    for (bool above : {true, false}) {
      CAPTURE(above);
      SpMat K = chain();
      K.coeffRef(above ? 1 : 3, above ? 3 : 1) = 0.3;  // (1, 3) or (3, 1) alone
      K.makeCompressed();                               // (as detMPs gives Kt)
      FreeSystem ldlt;
      ldlt.choice = LinearSolver::LDLT;
      const LinSolveOut c = chosenSolve(ldlt, {{0, 0.1}}, K, oobf, 1, {1, 2, 3, 4});
      const Eigen::VectorXd r = K * c.duvw - oobf;
      for (int d = 1; d < 5; ++d) CHECK(std::abs(r(d)) <= 1e-13);
      CHECK(ldlt.fallbacks == 1);
      CHECK(ldlt.factorisations == 1);                  // SparseLU's only
    }
  }
  // the old rule (same number of entries) would have kept the analysis of another pattern
  TEST_CASE("chosenSolve: the cache keeps its analysis while the pattern is the same, and rebuilds for another pattern with as many entries") {
    FreeSystem S;
    Eigen::VectorXd oobf(5);
    oobf << 0.7, 0.5, -1.0, 0.25, 2.0;
    chosenSolve(S, {{0, 0.1}}, chain(), oobf, 1, {1, 2, 3, 4});
    chosenSolve(S, {{0, 0.1}}, chain(), oobf, 2, {1, 2, 3, 4});
    CHECK(S.builds == 1);
    std::vector<Eigen::Triplet<double>> t;  // the chain with its last spring moved: 0-1, 1-2, 2-3, 2-4
    for (int i = 0; i < 4; ++i) {
      const int p = i < 3 ? i : 2, q = i + 1;
      const double k = i + 1.0;
      t.emplace_back(p, p, k), t.emplace_back(q, q, k), t.emplace_back(p, q, -k), t.emplace_back(q, p, -k);
    }
    SpMat K(5, 5);
    K.setFromTriplets(t.begin(), t.end());
    REQUIRE(K.nonZeros() == chain().nonZeros());
    const LinSolveOut o = chosenSolve(S, {{0, 0.1}}, K, oobf, 1, {1, 2, 3, 4});
    CHECK(S.builds == 2);
    const Eigen::VectorXd r = K * o.duvw - oobf;
    for (int d = 1; d < 5; ++d) CHECK(std::abs(r(d)) <= 1e-13);
  }
  // Kt's pattern changed only outside Kt(fd,fd) (two entries in the column of the prescribed
  // dof 4, stored after every free entry): Kt(fd,fd) and where its values sit in Kt are
  // unchanged, so the analysis is kept; other free dofs get a new one
  TEST_CASE("chosenSolve: the cache keeps its analysis when Kt's pattern changes only outside Kt(fd,fd)") {
    FreeSystem S;
    Eigen::VectorXd oobf(5);
    oobf << 0.7, 0.5, -1.0, 0.25, 2.0;
    const std::vector<int> fd{0, 1, 2, 3};
    const LinSolveOut a = chosenSolve(S, {{4, 0.1}}, chain(), oobf, 1, fd);
    SpMat K = chain();
    K.insert(0, 4) = 0.0;                                 // column 4: prescribed, stored after
    K.insert(2, 4) = 0.0;                                 // the free columns 0..3
    K.makeCompressed();
    REQUIRE(K.nonZeros() == chain().nonZeros() + 2);
    const LinSolveOut b = chosenSolve(S, {{4, 0.1}}, K, oobf, 1, fd);
    CHECK(S.builds == 1);
    CHECK((a.duvw - b.duvw).norm() == 0.0);               // (the same system: the same answer)
    K.insert(4, 2) = 0.0;                                 // column 2 grows: column 3's values move
    K.makeCompressed();
    const LinSolveOut c = chosenSolve(S, {{4, 0.1}}, K, oobf, 1, fd);
    CHECK(S.builds == 2);
    CHECK((a.duvw - c.duvw).norm() == 0.0);               // the values read where they now are
    chosenSolve(S, {{4, 0.1}}, K, oobf, 1, {0, 1, 3});     // other free dofs
    CHECK(S.builds == 3);
  }
  // a free entry that changes its row but not its place in Kt (column 0's rows {0, 1} become
  // {0, 2}): the positions fromKt knows still match, the pattern of Kt(fd,fd) does not
  TEST_CASE("chosenSolve: the cache rebuilds when a free entry of Kt moves to another row in the same place") {
    FreeSystem S;
    Eigen::VectorXd oobf(5);
    oobf << 0.7, 0.5, -1.0, 0.25, 2.0;
    const std::vector<int> fd{0, 1, 2, 3};
    chosenSolve(S, {{4, 0.1}}, chain(), oobf, 1, fd);
    std::vector<Eigen::Triplet<double>> t;
    const SpMat C = chain();
    for (int c = 0; c < C.outerSize(); ++c)
      for (SpMat::InnerIterator it(C, c); it; ++it)
        t.emplace_back(c == 0 && it.row() == 1 ? 2 : int(it.row()), c, it.value());
    SpMat K(5, 5);
    K.setFromTriplets(t.begin(), t.end());
    REQUIRE(K.nonZeros() == C.nonZeros());
    const LinSolveOut o = chosenSolve(S, {{4, 0.1}}, K, oobf, 1, fd);
    CHECK(S.builds == 2);
    const Eigen::VectorXd r = K * o.duvw - oobf;
    for (int d : fd) CHECK(std::abs(r(d)) <= 1e-13);
  }
  // [[e, 1], [1, e]] with e = 1e-18: symmetric and factorisable without pivoting, but LDL^T
  // takes the tiny pivot first (either order) and its solve is garbage; the backward error
  // sees it and SparseLU (pivoting) solves the pass: x = (b2, b1) to round-off
  TEST_CASE("linSolve: solver=LDLT hands an unstable factorisation (a tiny pivot) to SparseLU") {
    std::vector<Eigen::Triplet<double>> t{{0, 0, 1e-18}, {1, 1, 1e-18}, {0, 1, 1.0}, {1, 0, 1.0}};
    SpMat K(2, 2);
    K.setFromTriplets(t.begin(), t.end());
    Eigen::VectorXd oobf(2);
    oobf << 1.0, 2.0;
    FreeSystem S;
    S.choice = LinearSolver::LDLT;
    const LinSolveOut o = chosenSolve(S, {}, K, oobf, 2, {0, 1});
    CHECK(S.fallbacks == 1);
    CHECK(std::abs(o.duvw(0) - 2.0) <= 1e-12);
    CHECK(std::abs(o.duvw(1) - 1.0) <= 1e-12);
  }
  // springs alternately stiff (1e6) and soft (1) along 100 dofs, held at dof 0, pulled at the
  // end: cond(Kff) ~ 1e10, so a backward-stable solve leaves a relative residual well above
  // 1e-10 (measured 2.8e-8) while its backward error is round-off (7.5e-17); LDLT must be
  // accepted (a relative-residual test of 1e-10 sent every such pass to SparseLU) and give
  // the series-spring answer to cond * eps ~ 1e-6 (bound 1e-7; measured 1.1e-10, SparseLU 1.0e-8)
  TEST_CASE("linSolve: solver=LDLT accepts an ill-conditioned symmetric chain by its backward error, no fallback") {
    const int n = 100;
    std::vector<Eigen::Triplet<double>> t;
    Eigen::VectorXd k(n - 1);
    for (int i = 0; i + 1 < n; ++i) {
      k(i) = i % 2 ? 1e6 : 1.0;
      t.emplace_back(i, i, k(i)), t.emplace_back(i + 1, i + 1, k(i));
      t.emplace_back(i, i + 1, -k(i)), t.emplace_back(i + 1, i, -k(i));
    }
    SpMat K(n, n);
    K.setFromTriplets(t.begin(), t.end());
    Eigen::VectorXd oobf = Eigen::VectorXd::Zero(n);
    oobf(n - 1) = 1.0;
    std::vector<int> fd;
    for (int d = 1; d < n; ++d) fd.push_back(d);
    FreeSystem S;
    S.choice = LinearSolver::LDLT;
    const LinSolveOut o = chosenSolve(S, {}, K, oobf, 2, fd);
    CHECK(S.fallbacks == 0);
    double u = 0, err = 0;                                // series springs: u_j = sum_{i<j} 1 / k_i
    for (int j = 1; j < n; ++j) {
      u += 1.0 / k(j - 1);
      err = std::max(err, std::abs(o.duvw(j) - u) / u);
    }
    MESSAGE("ill-conditioned chain, LDLT: largest relative error ", err);
    CHECK(err <= 1e-7);
  }
  // measured: largest stress difference 5.0e-14 of the largest stress with LDLT (collapse
  // a = 1, von Mises, 40 steps; Kt(fd,fd) symmetric in every pass, no fallback)
  TEST_CASE("linSolve: a whole run with each solver= of this build equals SparseLU's to 1e-10") {
    RunLog l1;
    const Analysis lu = testing::runSetup("collapse", {{"a", 1}}, l1);
    for (LinearSolver choice : solvers(true)) {
      const std::string name = solverNames()[size_t(choice)];
      CAPTURE(name);
      RunLog l2;
      const Analysis other = testing::runSetup("collapse", {{"a", 1}, {"solver", int(choice)}}, l2);
      REQUIRE(l1.lastConverged == l2.lastConverged);
      double d = 0, big = 0;
      for (size_t p = 0; p < lu.mpData.size(); ++p) {
        d = std::max(d, (lu.mpData[p].sig - other.mpData[p].sig).cwiseAbs().maxCoeff());
        big = std::max(big, lu.mpData[p].sig.cwiseAbs().maxCoeff());
      }
      MESSAGE("collapse a = 1: LU vs ", name, " stress ", d / big);
      CHECK(d <= 1e-10 * big);
    }
  }
  // measured (a = 2, nfd = 144): 1.4e-15 (LDLT); the symmetric factorisations need no fallback
  // on this symmetric Kt
  TEST_CASE("linSolve: each solver= of this build solves the collapse's Kt(fd,fd) as SparseLU/COLAMD does, to 1e-10") {
    const CollapseStep1 c = collapseStep1();
    REQUIRE(c.fd.size() == 144);                          // 9 x 9 nodes less the supports
    Eigen::VectorXd oobf(c.Kt.rows());
    for (int i = 0; i < oobf.size(); ++i) oobf(i) = std::sin(i + 1.0);  // any load
    FreeSystem lu;
    const LinSolveOut a = chosenSolve(lu, {}, c.Kt, oobf, 2, c.fd);
    for (LinearSolver choice : solvers(true)) {
      CAPTURE(solverNames()[size_t(choice)]);
      FreeSystem S;
      S.choice = choice;
      const LinSolveOut b = chosenSolve(S, {}, c.Kt, oobf, 2, c.fd);
      MESSAGE(solverNames()[size_t(choice)], ": ", (a.duvw - b.duvw).norm() / a.duvw.norm());
      CHECK((a.duvw - b.duvw).norm() <= 1e-10 * a.duvw.norm());
      CHECK(S.fallbacks == 0);
      CHECK(S.builds == 1);
    }
  }
  // the chain's analytic solution with every choice; the unsymmetric chain goes to SparseLU
  // for the symmetric ones (a fallback, counted; MUMPS to its own LU); the unconstrained chain
  // is refused by all
  TEST_CASE("linSolve: each solver= of this build: the chain's analytic solution, the unsymmetric fallback, the singular chain") {
    Eigen::VectorXd oobf(5);
    oobf << 0.7, 0.5, -1.0, 0.25, 2.0;
    FreeSystem lu;
    const LinSolveOut a = chosenSolve(lu, {{0, 0.1}}, chain(), oobf, 1, {1, 2, 3, 4});
    SpMat K = chain();
    K.coeffRef(2, 3) += 0.5;                              // same pattern, no longer symmetric
    for (LinearSolver choice : solvers(true)) {
      CAPTURE(solverNames()[size_t(choice)]);
      FreeSystem S;
      S.choice = choice;
      const LinSolveOut b = chosenSolve(S, {{0, 0.1}}, chain(), oobf, 1, {1, 2, 3, 4});
      CHECK((a.duvw - b.duvw).norm() <= 1e-14 * a.duvw.norm());
      const LinSolveOut c = chosenSolve(S, {{0, 0.1}}, K, oobf, 1, {1, 2, 3, 4});
      const Eigen::VectorXd r = K * c.duvw - oobf;
      for (int d = 1; d < 5; ++d) CHECK(std::abs(r(d)) <= 1e-13);
      const bool ownLU = choice == LinearSolver::MUMPS || choice == LinearSolver::PETSC;  // an unsymmetric
                                                                                         // pass is theirs
      CHECK(S.fallbacks == (ownLU ? 0 : 1));
      CHECK(S.builds == 1);
      FreeSystem T;
      T.choice = choice;
      CHECK_THROWS_AS(chosenSolve(T, {}, chain(), Eigen::VectorXd::Ones(5), 1, {0, 1, 2, 3, 4}), RunError);
    }
  }
  // a choice this build lacks: InputError naming the parameter, the choices built and the
  // CMake option; the program exits 2 before any work (nothing to refuse when all are built)
  TEST_CASE("linSolve: a solver= this build lacks is refused, naming the choices built and the CMake option" *
            doctest::skip(everySolverBuilt())) {
    const Setup* s = findSetup("collapse");
    REQUIRE(s != nullptr);
    for (LinearSolver choice : solvers(false)) {
      const std::string name = solverNames()[size_t(choice)];
      const std::string option = choice == LinearSolver::MUMPS ? "-DAMPLE_MUMPS=ON" : "-DAMPLE_PETSC=ON";
      CAPTURE(name);
      Params P = s->params();
      setParam(P, "solver", int(choice));
      std::string message;
      try {
        s->setupGrid(P);
      } catch (const InputError& e) {
        message = e.what();
      }
      CHECK(message.find("solver=" + name + " is not in this build") != std::string::npos);
      CHECK(message.find("it has solver=" + solversBuilt()) != std::string::npos);
      CHECK(message.find(option) != std::string::npos);
      FreeSystem S;                                       // also when set in code, not by the setup
      S.choice = choice;
      CHECK_THROWS_AS(chosenSolve(S, {{0, 0.1}}, chain(), Eigen::VectorXd::Ones(5), 1, {1, 2, 3, 4}), InputError);
      const std::string out = std::string(AMPLE_TEST_TMP) + "/solver_refused";
      std::filesystem::create_directories(AMPLE_TEST_TMP);
      const std::string cmd = std::string(AMPLE_BINARY) + " collapse a=1 solver=" + name + " --quiet --out " +
                              out + " >/dev/null 2>" + out + ".err";
      const int st = std::system(cmd.c_str());
      CHECK((WIFEXITED(st) ? WEXITSTATUS(st) : -1) == 2);
      std::string line;
      std::getline(std::ifstream(out + ".err"), line);
      CHECK(line == "ample: " + message);
      CHECK(!std::filesystem::exists(out + "/summary.json"));
    }
  }
}


TEST_SUITE("linSolve") {
  // K = [4 -1 0; -1 3 -1; 0 -1 2] (symmetric, positive definite)
  SpMat three() {
    std::vector<Eigen::Triplet<double>> t{{0, 0, 4.0}, {0, 1, -1.0}, {1, 0, -1.0}, {1, 1, 3.0},
                                          {1, 2, -1.0}, {2, 1, -1.0}, {2, 2, 2.0}};
    SpMat K(3, 3);
    K.setFromTriplets(t.begin(), t.end());
    return K;
  }
  TEST_CASE("linSolve: a 3-dof system with the held dof first then last in turn: the solutions and reactions by hand") {
    for (int round = 0; round < 2; ++round) {
      CAPTURE(round);
      // dof 0 prescribed 0.2 at NRit = 1, oobf = (1, 2, -1): Kff = [3 -1; -1 2],
      // rhs = (2 + 0.2, -1), x = [2 1; 1 3] rhs / 5 = (0.68, -0.16), reaction 4 (0.2) - 0.68 - 1
      const LinSolveOut a = linSolve({{0, 0.2}}, three(), Eigen::Vector3d(1.0, 2.0, -1.0), 1, {1, 2});
      CHECK(a.duvw(0) == 0.2);
      CHECK(a.duvw(1) == doctest::Approx(0.68).epsilon(1e-14));
      CHECK(a.duvw(2) == doctest::Approx(-0.16).epsilon(1e-14));
      CHECK(a.drct(0) == doctest::Approx(-0.88).epsilon(1e-14));
      CHECK(a.drct(1) == 0.0);
      CHECK(a.drct(2) == 0.0);
      // dof 2 held at NRit = 2 (its value no longer applied), oobf = (0.5, -1, 3): Kff = [4 -1; -1 3],
      // x = [3 1; 1 4] (0.5, -1) / 11 = (0.5, -3.5) / 11, reaction -x1 - 3
      const LinSolveOut b = linSolve({{2, 0.7}}, three(), Eigen::Vector3d(0.5, -1.0, 3.0), 2, {0, 1});
      CHECK(b.duvw(2) == 0.0);
      CHECK(b.duvw(0) == doctest::Approx(0.5 / 11).epsilon(1e-14));
      CHECK(b.duvw(1) == doctest::Approx(-3.5 / 11).epsilon(1e-14));
      CHECK(b.drct(2) == doctest::Approx(3.5 / 11 - 3.0).epsilon(1e-14));
      // the same dof held at NRit = 1: its value enters, coupled to dof 1: rhs = (0.5, -1 + 0.7)
      const LinSolveOut c = linSolve({{2, 0.7}}, three(), Eigen::Vector3d(0.5, -1.0, 3.0), 1, {0, 1});
      CHECK(c.duvw(2) == 0.7);
      CHECK(c.duvw(0) == doctest::Approx((1.5 - 0.3) / 11).epsilon(1e-14));
      CHECK(c.duvw(1) == doctest::Approx((0.5 - 1.2) / 11).epsilon(1e-14));
      CHECK(c.drct(2) == doctest::Approx(-(0.5 - 1.2) / 11 + 1.4 - 3.0).epsilon(1e-14));
    }
  }
  TEST_CASE("linSolve: every dof prescribed (no free dof): no solve / duvw = the values / drct = Kt duvw - oobf") {
    const std::vector<BC> bc = {{0, 0.1}, {1, -0.2}, {2, 0.05}};
    const LinSolveOut o = linSolve(bc, three(), Eigen::Vector3d(1.0, 2.0, -1.0), 1, {});
    CHECK(o.duvw(0) == 0.1);
    CHECK(o.duvw(1) == -0.2);
    CHECK(o.duvw(2) == 0.05);
    // Kt u = (0.4 + 0.2, -0.1 - 0.6 - 0.05, 0.2 + 0.1) = (0.6, -0.75, 0.3)
    CHECK(o.drct(0) == doctest::Approx(0.6 - 1.0).epsilon(1e-14));
    CHECK(o.drct(1) == doctest::Approx(-0.75 - 2.0).epsilon(1e-14));
    CHECK(o.drct(2) == doctest::Approx(0.3 + 1.0).epsilon(1e-14));
    // at NRit = 2 nothing moves, and the reactions are the out-of-balance forces' opposite
    const LinSolveOut p = linSolve(bc, three(), Eigen::Vector3d(1.0, 2.0, -1.0), 2, {});
    CHECK(p.duvw.norm() == 0.0);
    CHECK((p.drct - Eigen::Vector3d(-1.0, -2.0, 1.0)).norm() == 0.0);
  }
  TEST_CASE("linSolve: linear in oobf and in the prescribed values (superposition) / the free equations balanced") {
    const SpMat K = chain();
    Eigen::VectorXd f1(5), f2(5);
    f1 << 0.3, -1.0, 0.5, 2.0, -0.7;
    f2 << -0.2, 0.4, 1.5, -0.6, 0.9;
    const std::vector<int> fd = {0, 1, 3, 4};
    const LinSolveOut a = linSolve({{2, 0.3}}, K, f1, 1, fd), b = linSolve({{2, -0.1}}, K, f2, 1, fd);
    const LinSolveOut ab = linSolve({{2, 0.2}}, K, f1 + f2, 1, fd);
    CHECK((ab.duvw - a.duvw - b.duvw).norm() <= 1e-13 * ab.duvw.norm());
    CHECK((ab.drct - a.drct - b.drct).norm() <= 1e-13 * ab.drct.norm());
    const Eigen::VectorXd r = K * ab.duvw - (f1 + f2);
    for (int d : fd) CHECK(std::abs(r(d)) <= 1e-13);
    CHECK(ab.drct(2) == doctest::Approx(r(2)).epsilon(1e-13));
    CHECK(ab.drct.sum() == doctest::Approx(-(f1 + f2).sum()).epsilon(1e-13));  // the chain's balance
  }
}

TEST_SUITE("linSolve") {
  // the core solves with SparseLU from scratch in every pass; chosenSolve (the program's for
  // large runs) keeps Kt(fd,fd)'s pattern and SparseLU's analysis: the same factors, bit for bit
  TEST_CASE("linSolve: the core's SparseLU and chosenSolve's kept analysis give the same increments bit for bit (collapse, passes 1 to 3)") {
    const CollapseStep1 c = collapseStep1();
    int held = -1;                                        // a prescribed dof: one not in fd
    for (int d = 0; d < c.Kt.rows() && held < 0; ++d)
      if (!std::binary_search(c.fd.begin(), c.fd.end(), d)) held = d;
    REQUIRE(held >= 0);
    const std::vector<BC> bc{{held, 0.01}};
    FreeSystem S;                                         // solver=LU, the default
    for (int NRit = 1; NRit <= 3; ++NRit) {
      CAPTURE(NRit);
      Eigen::VectorXd oobf(c.Kt.rows());
      for (int i = 0; i < oobf.size(); ++i) oobf(i) = std::cos(NRit * (i + 1.0));
      const LinSolveOut a = linSolve(bc, c.Kt, oobf, NRit, c.fd), b = chosenSolve(S, bc, c.Kt, oobf, NRit, c.fd);
      CHECK(a.duvw.norm() > 0);
      CHECK(a.duvw == b.duvw);
      CHECK(a.drct == b.drct);
      CHECK(a.duvw(held) == (NRit == 1 ? 0.01 : 0.0));
    }
    CHECK(S.builds == 1);                                 // analysed once for the three passes
  }
}

// solver=MUMPS (built with -DAMPLE_MUMPS=ON): the negative pivots of its LDL^T are the
// negative eigenvalues of K (Sylvester's law of inertia), against the analytic spectrum of
// tridiag(-1, d, -1) of order n, d - 2 cos(k pi / (n + 1)), k = 1..n; the solve against a
// dense LU; and a run's steps.csv and summary.json carry them
TEST_SUITE("linSolve") {
  TEST_CASE("linSolve: MUMPS's negative pivots count the negative eigenvalues of an indefinite Kt(fd,fd) (tridiagonal: analytic)" *
            doctest::skip(!solverBuilt(LinearSolver::MUMPS))) {
    const int n = 40;
    for (double d : {3.0, 1.0, 0.5, -0.7, -3.0}) {
      CAPTURE(d);
      std::vector<Eigen::Triplet<double>> t;
      for (int i = 0; i < n; ++i) {
        t.emplace_back(i, i, d);
        if (i > 0) t.emplace_back(i, i - 1, -1.0), t.emplace_back(i - 1, i, -1.0);
      }
      SpMat K(n, n);
      K.setFromTriplets(t.begin(), t.end());
      int negative = 0;                                   // the analytic count
      for (int k = 1; k <= n; ++k) negative += d - 2.0 * std::cos(k * M_PI / (n + 1)) < 0;
      FreeSystem S;
      S.choice = LinearSolver::MUMPS;
      std::vector<int> fd(n);
      for (int i = 0; i < n; ++i) fd[i] = i;
      const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
      const Eigen::VectorXd x = chosenSolveFree(S, K, fd, b, 1);
      CHECK(S.negativePivots == negative);
      const Eigen::VectorXd ref = Eigen::MatrixXd(K).partialPivLu().solve(b);
      CHECK((x - ref).norm() <= 1e-12 * ref.norm());
    }
  }

  TEST_CASE("linSolve: solver=MUMPS writes each step's negative pivots (steps.csv) and the last and first (summary.json); an elastic tangent has none" *
            doctest::skip(!solverBuilt(LinearSolver::MUMPS))) {
    const std::string out = std::string(AMPLE_TEST_TMP) + "/mumps_pivots";
    std::filesystem::create_directories(AMPLE_TEST_TMP);
    const std::string cmd = std::string(AMPLE_BINARY) + " collapse a=1 solver=MUMPS --vtk 0 --quiet --out " + out +
                            " >/dev/null 2>&1";
    REQUIRE(std::system(cmd.c_str()) == 0);
    std::ifstream steps(out + "/steps.csv");
    std::string line;
    std::getline(steps, line);
    CHECK(line == "lstp,load_factor,NRit,fErr,converged,negative_pivots,seconds");
    int rows = 0, last = -1, from = 0;
    while (std::getline(steps, line)) {
      std::vector<std::string> f;
      size_t at = 0;
      for (size_t c; (c = line.find(',', at)) != std::string::npos; at = c + 1) f.push_back(line.substr(at, c - at));
      REQUIRE(f.size() == 6);
      const int pivots = std::atoi(f[5].c_str());
      if (rows == 0) CHECK(pivots == 0);                 // step 1 is elastic: Kt(fd,fd) positive definite
      last = pivots;
      if (from == 0 && pivots > 0) from = std::atoi(f[0].c_str());
      rows++;
    }
    CHECK(rows == 40);
    std::ifstream json(out + "/summary.json");
    const std::string text((std::istreambuf_iterator<char>(json)), std::istreambuf_iterator<char>());
    CHECK(text.find("\"negative_pivots\": " + std::to_string(last) + ",") != std::string::npos);
    CHECK(text.find("\"negative_pivots_from\": " + std::to_string(from)) != std::string::npos);
  }
}
