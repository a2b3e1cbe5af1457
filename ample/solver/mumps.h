//--------------------------------------------------------------------------
// mumps — Kt(fd,fd) x = rhs by MUMPS (solver=MUMPS, built with -DAMPLE_MUMPS=ON)
//--------------------------------------------------------------------------
// MUMPS 5 (Amestoy, Duff, L'Excellent, Koster 2001), the sequential library of
// Debian's libmumps-seq-dev: a multifrontal factorisation on dense fronts.
// A symmetric Kt(fd,fd) goes to its general symmetric mode (SYM = 2: LDL^T with
// 1 x 1 and 2 x 2 pivots, so an indefinite tangent factorises too), given its
// lower triangle; an unsymmetric one to its LU (SYM = 0). Each mode has its own
// MUMPS instance; factorize orders the pattern on the first call of a mode after
// newPattern (JOB = 1, on the pattern alone, so the same values give the same
// numbers whenever it ran), then factorises the values (JOB = 2, every pass);
// solve solves with the last factorisation (JOB = 3). Ordering AMF (ICNTL(7) = 2:
// the same in every run), diagonal scaling (ICNTL(8) = 1); MUMPS's working space
// stays in the process's heap between factorisations (glibc's mallopt, set once:
// mumps.cpp).
// negativePivots: INFOG(12) of the last LDL^T, the number of negative
// eigenvalues of Kt(fd,fd) (Sylvester's law of inertia); -1 after an LU.
// Inputs:  K (nfd x nfd, compressed) · rhs (nfd)
// Outputs: x (nfd) · negativePivots · false and message() where MUMPS fails
//          (a numerically singular K: INFOG(1) = -10)
// Tests:   tests/test_linSolve.cpp (every solver= of the build)
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"
#include <memory>
#include <string>

namespace ample {

class MumpsSolver {
 public:
  MumpsSolver();
  ~MumpsSolver();
  MumpsSolver(const MumpsSolver&);             // a copy starts unanalysed (MUMPS keeps
  MumpsSolver& operator=(const MumpsSolver&);  // its factors behind its own handle)
  void newPattern();                                     // K's pattern changed: analyse again
  bool factorize(const SpMat& K, bool symmetric);       // false: failed (message())
  int analyses() const { return analyses_; }            // JOB = 1 runs so far
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs);    // with the last factorisation
  int negativePivots() const { return negativePivots_; }
  const std::string& message() const { return message_; }

 private:
  struct Instance;                                      // one MUMPS instance and its matrix
  std::unique_ptr<Instance> sym_, lu_;
  Instance* last_ = nullptr;                            // the one that factorised last
  int negativePivots_ = -1;
  int analyses_ = 0;
  std::string message_;
};

}  // namespace ample
