//--------------------------------------------------------------------------
// freeSystem — Kt(fd,fd) of one load step, its pattern and its symbolic analysis
//--------------------------------------------------------------------------
// See freeSystem.h for what it saves, inputs and outputs.
//--------------------------------------------------------------------------
#include "freeSystem.h"
#include <algorithm>

namespace ample {

void extractFreeSystem(const SpMat& Kt, const std::vector<int>& fd, FreeSystem& S) {
  eigen_assert(Kt.isCompressed() && std::is_sorted(fd.begin(), fd.end()));  // (freeSystem.h)
  const int nfd = int(fd.size());
  const int *outer = Kt.outerIndexPtr(), *inner = Kt.innerIndexPtr();
  std::vector<int> freeIdx(Kt.rows(), -1);              // global dof -> row of Kt(fd,fd)
  for (int r = 0; r < nfd; ++r) freeIdx[fd[r]] = r;
  long nnz = 0;                                         // entries of Kt(fd,fd), counted first:
  for (int c : fd)                                      // Kff and fromKt get their exact size
    for (int e = outer[c]; e < outer[c + 1]; ++e) nnz += freeIdx[inner[e]] >= 0;
  S.Kff = SpMat(nfd, nfd);                              // the last pattern's memory goes first
  S.Kff.reserve(nnz);
  S.fromKt.resize(nnz);
  long k = 0;                                           // column c of Kt(fd,fd) is column fd[c] of
  for (int c = 0; c < nfd; ++c) {                       // Kt less its fixed rows; fd ascending and
    S.Kff.startVec(c);                                  // Kt's rows sorted: they come in order
    for (int e = outer[fd[c]]; e < outer[fd[c] + 1]; ++e)
      if (freeIdx[inner[e]] >= 0) {
        S.Kff.insertBack(freeIdx[inner[e]], c) = Kt.valuePtr()[e];
        S.fromKt[k++] = e;
      }
  }
  S.Kff.finalize();
}

void buildFreeSystem(const SpMat& Kt, const std::vector<int>& fd, FreeSystem& S) {
  checkSolverBuilt(S.choice);
  extractFreeSystem(Kt, fd, S);
  S.luAnalysed = false;                                 // LU (or a fallback) analyses it when needed
  S.mirror.clear();                                     // found at the first symmetry check
  switch (S.choice) {                                   // symbolic analysis, once per pattern
    case LinearSolver::LU: break;
    case LinearSolver::LDLT: S.ldlt.analyzePattern(S.Kff); break;
#ifdef AMPLE_HAVE_MUMPS
    case LinearSolver::MUMPS: S.mumps.newPattern(); break;  // analysed at its first factorisation
#endif
#ifdef AMPLE_HAVE_PETSC
    case LinearSolver::PETSC: S.petsc.newPattern(); break;  // built at its first solve
#endif
    default: break;                                     // not built: refused above
  }
  S.fd = fd;
  S.ktRows = int(Kt.rows());
  S.builds++;
}

// Kt has the pattern S was built for (the same step, or a step whose points link the same
// nodes): the same free dofs, and Kt's entries in free rows and columns sit where fromKt
// says and land where Kff has them (walked as extractFreeSystem does; no copy of Kt kept)
static bool samePattern(const SpMat& Kt, const std::vector<int>& fd, const FreeSystem& S) {
  if (S.fd != fd || S.Kff.rows() != int(fd.size()) || S.ktRows != Kt.rows()) return false;
  const int *outer = Kt.outerIndexPtr(), *inner = Kt.innerIndexPtr();
  const int *kffOuter = S.Kff.outerIndexPtr(), *kffInner = S.Kff.innerIndexPtr();
  std::vector<char> isFree(Kt.rows(), 0);
  for (int c : fd) isFree[c] = 1;
  long k = 0;
  for (size_t c = 0; c < fd.size(); ++c) {
    if (kffOuter[c] != k) return false;
    for (int e = outer[fd[c]]; e < outer[fd[c] + 1]; ++e)
      if (isFree[inner[e]]) {
        if (k == S.Kff.nonZeros() || S.fromKt[k] != e || fd[kffInner[k]] != inner[e]) return false;
        ++k;
      }
  }
  return k == S.Kff.nonZeros();
}

void refillFreeSystem(const SpMat& Kt, const std::vector<int>& fd, FreeSystem& S) {
  if (!samePattern(Kt, fd, S)) buildFreeSystem(Kt, fd, S);
  for (int e = 0; e < S.Kff.nonZeros(); ++e) S.Kff.valuePtr()[e] = Kt.valuePtr()[S.fromKt[e]];
}

}  // namespace ample
