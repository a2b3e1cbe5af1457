//--------------------------------------------------------------------------
// petscSolve — Kt(fd,fd) x = rhs by PETSc over MPI ranks (solver=PETSC)
//--------------------------------------------------------------------------
// See petscSolve.h for inputs and outputs.
//--------------------------------------------------------------------------
#ifdef AMPLE_HAVE_PETSC                                 // (a build without it: nothing)
#include "petscSolve.h"
#include <petscksp.h>
#include <cstdlib>
#include <string>
#include <vector>

namespace ample {

static bool started = false;                            // PetscInitialize ran here

// the options of the server and its inner solver, on every rank before PetscInitialize
// (the server's ranks never leave it); PETSC_OPTIONS, read by PetscInitialize, may override
static void startPetsc() {
  if (started) return;
  PetscOptionsSetValue(nullptr, "-mpi_linear_solver_server", nullptr);
  PetscOptionsSetValue(nullptr, "-mpi_ksp_type", "preonly");
  PetscOptionsSetValue(nullptr, "-mpi_pc_type", "lu");
  PetscOptionsSetValue(nullptr, "-mpi_pc_factor_mat_solver_type", "mumps");
  PetscOptionsSetValue(nullptr, "-pc_mpi_minimum_count_per_rank", "2000");
  for (const char* prefix : {"-mpi_", "-sym_mpi_"}) {              // MUMPS as solver=MUMPS sets it:
    PetscOptionsSetValue(nullptr, (std::string(prefix) + "mat_mumps_icntl_7").c_str(), "2");  // AMF,
    PetscOptionsSetValue(nullptr, (std::string(prefix) + "mat_mumps_icntl_8").c_str(), "1");  // diagonal
  }                                                                 // scaling (mumps.cpp)
  PetscOptionsSetValue(nullptr, "-sym_mpi_ksp_type", "preonly");  // a symmetric Kt(fd,fd): MUMPS's
  PetscOptionsSetValue(nullptr, "-sym_mpi_pc_type", "cholesky");  // LDL^T (indefinite too)
  PetscOptionsSetValue(nullptr, "-sym_mpi_pc_factor_mat_solver_type", "mumps");
  PetscOptionsSetValue(nullptr, "-sym_pc_mpi_minimum_count_per_rank", "2000");
  PetscInitialize(nullptr, nullptr, nullptr, nullptr);
  started = true;
}

void petscStart() {
  const bool launched = std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") ||
                        std::getenv("PMIX_RANK");      // mpirun / mpiexec (Open MPI, MPICH)
  if (launched) startPetsc();
}

void petscEnd() {
  if (started) PetscFinalize();
  started = false;
}

struct PetscSolver::Impl {
  Mat A = nullptr;
  KSP ksp = nullptr, kspSym = nullptr;                  // LU; LDL^T (options prefix sym_)
  Vec b = nullptr, x = nullptr;
  std::vector<PetscInt> rowStart, column;               // Kff's pattern by rows (CSR)
  std::vector<int> fromKff;                             // CSR entry e is Kff's value fromKff[e]

  ~Impl() { clear(); }
  void clear() {
    if (ksp) KSPDestroy(&ksp);
    if (kspSym) KSPDestroy(&kspSym);
    if (A) MatDestroy(&A);
    if (b) VecDestroy(&b);
    if (x) VecDestroy(&x);
  }

  // the sequential AIJ matrix of Kff's pattern (its columns read into rows), the vectors, the KSP
  bool build(const SpMat& K) {
    const int n = int(K.rows());
    rowStart.assign(n + 1, 0);
    for (int e = 0; e < K.nonZeros(); ++e) rowStart[K.innerIndexPtr()[e] + 1]++;
    for (int r = 0; r < n; ++r) rowStart[r + 1] += rowStart[r];
    column.assign(K.nonZeros(), 0);
    fromKff.assign(K.nonZeros(), 0);
    std::vector<PetscInt> next(rowStart.begin(), rowStart.end() - 1);
    for (int c = 0; c < n; ++c)                         // columns in order: each row's sorted
      for (int e = K.outerIndexPtr()[c]; e < K.outerIndexPtr()[c + 1]; ++e) {
        const PetscInt at = next[K.innerIndexPtr()[e]]++;
        column[at] = c;
        fromKff[at] = e;
      }
    std::vector<PetscInt> perRow(n);
    for (int r = 0; r < n; ++r) perRow[r] = rowStart[r + 1] - rowStart[r];
    if (MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 0, perRow.data(), &A) ||
        MatSeqAIJSetPreallocationCSR(A, rowStart.data(), column.data(), nullptr) ||
        MatSetOption(A, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE) || MatCreateVecs(A, &x, &b))
      return false;
    return makeKsp(ksp, "") && makeKsp(kspSym, "sym_");
  }

  // a KSP that hands A to the server (PCMPI) and solves it once, with the options of prefix
  bool makeKsp(KSP& k, const char* prefix) {
    PC pc;
    return !(KSPCreate(PETSC_COMM_SELF, &k) || KSPSetOptionsPrefix(k, prefix) || KSPSetType(k, KSPPREONLY) ||
             KSPSetOperators(k, A, A) || KSPGetPC(k, &pc) || PCSetType(pc, PCMPI) || KSPSetFromOptions(k));
  }
};

PetscSolver::PetscSolver() = default;
PetscSolver::~PetscSolver() = default;
PetscSolver::PetscSolver(const PetscSolver&) {}
PetscSolver& PetscSolver::operator=(const PetscSolver& other) {
  if (this != &other) p_.reset(), message_.clear();
  return *this;
}

void PetscSolver::newPattern() { p_.reset(); }

bool PetscSolver::solve(const SpMat& Kff, const Eigen::VectorXd& rhs, Eigen::VectorXd& out, bool symmetric) {
  startPetsc();                                         // one process: PETSc starts here
  message_.clear();
  if (!p_) {
    p_ = std::make_unique<Impl>();
    if (!p_->build(Kff)) {
      p_.reset();
      message_ = "PETSc could not set up Kt(fd,fd)";
      return false;
    }
  }
  PetscScalar* a;
  if (MatSeqAIJGetArray(p_->A, &a)) return message_ = "PETSc: MatSeqAIJGetArray failed", false;
  for (size_t e = 0; e < p_->fromKff.size(); ++e) a[e] = Kff.valuePtr()[p_->fromKff[e]];
  MatSeqAIJRestoreArray(p_->A, &a);                     // the values changed: a new factorisation
  PetscScalar* v;
  VecGetArray(p_->b, &v);
  for (Eigen::Index r = 0; r < rhs.size(); ++r) v[r] = rhs(r);
  VecRestoreArray(p_->b, &v);
  KSPConvergedReason reason = KSP_DIVERGED_PC_FAILED;
  KSP ksp = symmetric ? p_->kspSym : p_->ksp;
  if (KSPSolve(ksp, p_->b, p_->x) || KSPGetConvergedReason(ksp, &reason) || reason < 0) {
    message_ = "PETSc (MUMPS over the MPI ranks) could not solve Kt(fd,fd) (KSPConvergedReason " +
               std::to_string(int(reason)) + ")";
    p_.reset();                                         // start afresh at the next solve
    return false;
  }
  out.resize(rhs.size());
  const PetscScalar* s;
  VecGetArrayRead(p_->x, &s);
  for (Eigen::Index r = 0; r < rhs.size(); ++r) out(r) = s[r];
  VecRestoreArrayRead(p_->x, &s);
  return true;
}

}  // namespace ample
#endif
