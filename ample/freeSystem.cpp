//--------------------------------------------------------------------------
// freeSystem — Kt(fd,fd) of one load step, its pattern and its symbolic analysis
//--------------------------------------------------------------------------
// See freeSystem.h for what it saves, inputs and outputs.
//--------------------------------------------------------------------------
#include "freeSystem.h"
#include <algorithm>

namespace ample {

void extractFreeSystem(const SpMat& Kt, const std::vector<int>& fd, FreeSystem& S) {
  const int nfd = int(fd.size());
  std::vector<int> freeIdx(Kt.rows(), -1);              // global dof -> row of Kt(fd,fd)
  for (int r = 0; r < nfd; ++r) freeIdx[fd[r]] = r;
  std::vector<Eigen::Triplet<double>> trip;             // value = position of the entry in Kt
  for (int c = 0; c < Kt.outerSize(); ++c)
    if (freeIdx[c] >= 0)
      for (int e = Kt.outerIndexPtr()[c]; e < Kt.outerIndexPtr()[c + 1]; ++e)
        if (freeIdx[Kt.innerIndexPtr()[e]] >= 0)
          trip.emplace_back(freeIdx[Kt.innerIndexPtr()[e]], freeIdx[c], double(e));
  S.Kff = SpMat(nfd, nfd);
  S.Kff.setFromTriplets(trip.begin(), trip.end());      // no duplicates: each value is one e
  S.fromKt.resize(S.Kff.nonZeros());
  for (int e = 0; e < S.Kff.nonZeros(); ++e) S.fromKt[e] = int(S.Kff.valuePtr()[e]);
  for (int e = 0; e < S.Kff.nonZeros(); ++e) S.Kff.valuePtr()[e] = Kt.valuePtr()[S.fromKt[e]];
}

void buildFreeSystem(const SpMat& Kt, const std::vector<int>& fd, FreeSystem& S) {
  checkSolverBuilt(S.choice);
  extractFreeSystem(Kt, fd, S);
  S.luAnalysed = false;                                 // LU (or a fallback) analyses it when needed
  switch (S.choice) {                                   // symbolic analysis, once per pattern
    case LinearSolver::LU: break;
    case LinearSolver::LDLT: S.ldlt.analyzePattern(S.Kff); break;
#ifdef AMPLE_HAVE_METIS
    case LinearSolver::LDLT_METIS: S.ldltMetis.analyzePattern(S.Kff); break;
#endif
#ifdef AMPLE_HAVE_SUITESPARSE
    case LinearSolver::CHOLMOD:
      S.cholmod.cholmod().print = 0;                    // not positive definite: our fallback says so
      S.cholmod.analyzePattern(S.Kff);
      break;
    case LinearSolver::UMFPACK: S.umfpack.analyzePattern(S.Kff); break;
#endif
    default: break;                                     // not built: refused above
  }
  S.fd = fd;
  S.ktOuter.assign(Kt.outerIndexPtr(), Kt.outerIndexPtr() + Kt.outerSize() + 1);
  S.ktInner.assign(Kt.innerIndexPtr(), Kt.innerIndexPtr() + Kt.nonZeros());
  S.builds++;
}

// Kt has the pattern S was built for (the same step, or a step whose points link the same nodes)
static bool samePattern(const SpMat& Kt, const FreeSystem& S) {
  return S.ktOuter.size() == size_t(Kt.outerSize() + 1) && S.ktInner.size() == size_t(Kt.nonZeros()) &&
         std::equal(S.ktOuter.begin(), S.ktOuter.end(), Kt.outerIndexPtr()) &&
         std::equal(S.ktInner.begin(), S.ktInner.end(), Kt.innerIndexPtr());
}

void refillFreeSystem(const SpMat& Kt, const std::vector<int>& fd, FreeSystem& S) {
  if (S.fd != fd || !samePattern(Kt, S)) buildFreeSystem(Kt, fd, S);
  for (int e = 0; e < S.Kff.nonZeros(); ++e) S.Kff.valuePtr()[e] = Kt.valuePtr()[S.fromKt[e]];
}

}  // namespace ample
