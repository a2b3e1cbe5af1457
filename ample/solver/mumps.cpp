//--------------------------------------------------------------------------
// mumps — Kt(fd,fd) x = rhs by MUMPS (solver=MUMPS)
//--------------------------------------------------------------------------
// See mumps.h for inputs and outputs. ICNTL and INFOG below are MUMPS's
// 1-based names (icntl[k - 1] in C), as its users' guide writes them.
//--------------------------------------------------------------------------
#ifdef AMPLE_HAVE_MUMPS                                 // (a build without it: nothing)
#include "mumps.h"
#include <dmumps_c.h>
#include <cmath>
#include <vector>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace ample {

// MUMPS allocates its working space (a few hundred MB at 66,306 dofs) at every numeric
// factorisation and frees it after; glibc hands blocks that large back to the system, so
// every factorisation faulted in and zeroed its pages again: 7 % of the collapse a = 32's
// run time in the kernel (perf, 2026-12-05). Kept in the heap instead (as an MPI library
// that pins memory does too: PETSc's runs did not pay it), once per process
static void keepLargeBlocks() {
#if defined(__GLIBC__)
  static const bool once = [] {
    mallopt(M_MMAP_MAX, 0);                             // no block of its own mapping
    mallopt(M_TRIM_THRESHOLD, 1 << 30);                 // the heap's top kept up to 1 GiB free
    return true;
  }();
  (void)once;
#endif
}

struct MumpsSolver::Instance {
  DMUMPS_STRUC_C id{};
  bool symmetric = false;
  bool analysed = false;
  std::vector<MUMPS_INT> irn, jcn;                      // the entries given (1-based)
  std::vector<double> a;
  std::vector<int> fromK;                               // entry k is K's value fromK[k]

  explicit Instance(bool sym) : symmetric(sym) {
    keepLargeBlocks();
    id.job = -1;                                        // initialise
    id.par = 1;                                         // the host works too (one process)
    id.sym = sym ? 2 : 0;                               // general symmetric LDL^T, or LU
    id.comm_fortran = -987654;                          // MPI_COMM_WORLD (the sequential stub)
    dmumps_c(&id);
    id.icntl[0] = -1, id.icntl[1] = -1, id.icntl[2] = -1, id.icntl[3] = 0;  // ICNTL(1-4): silent
    id.icntl[5] = 0;                                    // ICNTL(6): no permutation by values,
    id.icntl[11] = 1;                                   // ICNTL(12): plain ordering: the analysis
                                                        // reads the pattern alone;
    id.icntl[6] = 2;                                    // ICNTL(7): AMF, PETSc's choice too (the
                                                        // automatic one takes SCOTCH above some
                                                        // size, whose runs differed in round-off);
    id.icntl[7] = 1;                                    // ICNTL(8): diagonal scaling, not the
  }                                                     // iterative one: the same passes and points
                                                        // to 1e-13, linSolve 5-12 % faster
  ~Instance() {
    id.job = -2;                                        // free MUMPS's memory
    dmumps_c(&id);
  }
  Instance(const Instance&) = delete;
  Instance& operator=(const Instance&) = delete;

  // JOB = 1 with the pattern of K (its lower triangle when symmetric)
  void analyse(const SpMat& K) {
    irn.clear(), jcn.clear(), fromK.clear();
    for (int c = 0; c < K.outerSize(); ++c)
      for (int e = K.outerIndexPtr()[c]; e < K.outerIndexPtr()[c + 1]; ++e) {
        const int r = K.innerIndexPtr()[e];
        if (symmetric && r < c) continue;
        irn.push_back(r + 1), jcn.push_back(c + 1), fromK.push_back(e);
      }
    a.assign(fromK.size(), 0.0);
    id.n = MUMPS_INT(K.rows());
    id.nnz = MUMPS_INT8(fromK.size());
    id.irn = irn.data(), id.jcn = jcn.data(), id.a = nullptr;
    id.job = 1;
    dmumps_c(&id);
    analysed = id.infog[0] >= 0;
  }

  // JOB = 2 with K's values; a workspace too small (INFOG(1) = -8, -9) is given more and retried
  bool factorise(const SpMat& K) {
    for (size_t k = 0; k < fromK.size(); ++k) a[k] = K.valuePtr()[fromK[k]];
    id.a = a.data();
    for (int tries = 0; tries < 4; ++tries) {
      id.job = 2;
      dmumps_c(&id);
      if (id.infog[0] != -8 && id.infog[0] != -9) break;
      id.icntl[13] = 2 * id.icntl[13] + 20;             // ICNTL(14): % more working space
    }
    return id.infog[0] >= 0;
  }
};

MumpsSolver::MumpsSolver() = default;
MumpsSolver::~MumpsSolver() = default;
MumpsSolver::MumpsSolver(const MumpsSolver&) {}
MumpsSolver& MumpsSolver::operator=(const MumpsSolver& other) {
  if (this != &other) sym_.reset(), lu_.reset(), last_ = nullptr, negativePivots_ = -1, message_.clear();
  return *this;
}

void MumpsSolver::newPattern() {
  if (sym_) sym_->analysed = false;
  if (lu_) lu_->analysed = false;
  last_ = nullptr;
}

bool MumpsSolver::factorize(const SpMat& K, bool symmetric) {
  std::unique_ptr<Instance>& mode = symmetric ? sym_ : lu_;
  if (!mode) mode = std::make_unique<Instance>(symmetric);
  Instance* s = mode.get();
  message_.clear();
  negativePivots_ = -1;
  last_ = nullptr;
  if (!s->analysed) {                                   // once per pattern and mode
    s->analyse(K);
    analyses_++;
  }
  if (!s->analysed) {
    message_ = "MUMPS could not analyse Kt(fd,fd) (INFOG(1) = " + std::to_string(s->id.infog[0]) + ")";
    return false;
  }
  if (!s->factorise(K)) {
    message_ = "MUMPS could not factorise Kt(fd,fd) (INFOG(1) = " + std::to_string(s->id.infog[0]) +
               ", INFOG(2) = " + std::to_string(s->id.infog[1]) +
               (s->id.infog[0] == -10 ? ": numerically singular)" : ")");
    return false;
  }
  if (symmetric) negativePivots_ = s->id.infog[11];     // INFOG(12)
  last_ = s;
  return true;
}

Eigen::VectorXd MumpsSolver::solve(const Eigen::VectorXd& rhs) {
  Eigen::VectorXd x = rhs;
  if (!last_) return Eigen::VectorXd::Constant(rhs.size(), NAN);
  last_->id.rhs = x.data();
  last_->id.nrhs = 1, last_->id.lrhs = MUMPS_INT(x.size());
  last_->id.job = 3;
  dmumps_c(&last_->id);
  if (last_->id.infog[0] < 0) x.setConstant(NAN);
  return x;
}
}  // namespace ample
#endif
