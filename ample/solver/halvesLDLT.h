//--------------------------------------------------------------------------
// halvesLDLT — LDL^T of Kt(fd,fd) as two halves and the interface between them
//--------------------------------------------------------------------------
// A fast part (solver=LDLT_HALVES, docs/solvers.md "Two halves at once"); no
// equation of the papers: the same linear system of [AMPLE] eq 29, solved
// by one level of nested dissection so that two cores share the factorisation.
// splitInTwo: with the dofs' positions, a straight cut at the median across
//   the longer extent; the dofs of one side with a neighbour (an entry of K)
//   on the other are the interface s (the side with fewer such dofs). With
//   none (a K alone): a breadth-first level structure of K's graph from a
//   pseudo-peripheral dof, the level that best balances the dofs before and
//   after it (fewest of max(before, after) + its own) is the interface. No
//   entry of K joins half 1 to half 2 either way.
// HalvesLDLT, with K ordered [1 2 s] and A_ij its blocks:
//   half i (i = 1, 2) factorises K_i = [A_ii A_is; A_si A_ss] = L_i D_i L_i^T,
//   interior by AMD, interface last: the interface block of L_i D_i L_i^T is
//   T_i = A_ss - A_si A_ii^-1 A_is; the two halves run on two threads at
//   once, and do the same arithmetic on one (results do not depend on it);
//   the interface solves S x_s = g with S = T_1 + T_2 - A_ss (the Schur
//   complement of A_ss, dense, Eigen::LDLT);
//   solve: forward through each half's interior, g = b_s + both halves'
//   interface parts, x_s = S^-1 g, back through each half with x_s known.
// Inputs:  K (n x n, symmetric, compressed, both triangles: Kt(fd,fd))
// Outputs: info() (NumericalIssue: a zero pivot in a half, or S singular) ·
//          solve(b) = K^-1 b · the split (interfaceSize, halfSize)
// Tests:   tests/test_halvesLDLT.cpp
//--------------------------------------------------------------------------
#pragma once
#include "stiffnessPattern.h"
#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <array>
#include <vector>

namespace ample {

// the dofs of half 1, half 2 and the interface (indices of K, ascending); at: where each dof's
// node is (none: by K's graph alone)
std::array<std::vector<int>, 3> splitInTwo(const SpMat& K, const std::vector<Eigen::Vector2d>& at = {});

class HalvesLDLT {
 public:
  // split (by `at`, where each dof's node is, if given), orderings, symbolic analyses (once a pattern)
  void analyzePattern(const SpMat& K, const std::vector<Eigen::Vector2d>& at = {});
  void factorize(const SpMat& K);       // K with the pattern analysed
  Eigen::ComputationInfo info() const { return info_; }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  int interfaceSize() const { return int(interface_.size()); }
  int halfSize(int i) const { return half_[i].n; }

 private:
  struct AsGiven {  // the ordering: K_i comes ordered (interior by AMD, interface last)
    template <class M> void operator()(const M& A, Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>& p) {
      p.setIdentity(A.rows());
    }
  };
  using Factor = Eigen::SimplicialLDLT<SpMat, Eigen::Upper, AsGiven>;
  struct Half {
    std::vector<int> dofs;    // K's dofs in this half's order: interior (AMD), then the interface
    int n = 0;                // interior dofs
    SpMat K;                  // K(dofs, dofs), upper triangle
    std::vector<int> fromK;   // value e of this K is value fromK[e] of K
    Factor ldlt;              // L_i D_i L_i^T
    Eigen::MatrixXd T;        // T_i (interface x interface)
  };
  void factorizeHalf(Half& h);
  void forward(const Half& h, Eigen::VectorXd& v, Eigen::VectorXd& g) const;
  void backward(const Half& h, Eigen::VectorXd& v, const Eigen::VectorXd& xs) const;
  std::array<Half, 2> half_;
  std::vector<int> interface_;
  Eigen::MatrixXd Ass_;                 // A_ss, dense
  std::vector<std::array<int, 3>> fromKss_;  // A_ss(r, c) is value e of K: {r, c, e}
  Eigen::LDLT<Eigen::MatrixXd> S_;
  Eigen::ComputationInfo info_ = Eigen::InvalidInput;
};

}  // namespace ample
