//--------------------------------------------------------------------------
// pointShares — the point loops of detMPs and elemMPinfo on several threads
//--------------------------------------------------------------------------
// See pointShares.h.
//--------------------------------------------------------------------------
#include "pointShares.h"
#include <algorithm>
#include <cstdlib>
#include <exception>
#include <vector>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace ample {

int pointsPerThread() {
  static const int least = [] {                                // read once
    const char* v = std::getenv("AMPLE_POINTS_PER_THREAD");
    char* end = nullptr;
    const long n = v ? std::strtol(v, &end, 10) : 0;
    return (v && *v && *end == 0 && n >= 1 && n <= (1 << 30)) ? int(n) : 2048;
  }();
  return least;
}

int pointThreads(int np) {
#ifdef _OPENMP
  return std::max(1, std::min(omp_get_max_threads(), np / pointsPerThread()));
#else
  (void)np;
  return 1;
#endif
}

void forPointShares(int np, int nt, const std::function<void(int t, int begin, int end)>& work) {
  if (nt <= 1) return work(0, 0, np);
  std::vector<std::exception_ptr> failed(nt);                  // a point that threw, per share
  auto share = [&](int t) {
    try {
      work(t, int(long(np) * t / nt), int(long(np) * (t + 1) / nt));
    } catch (...) {
      failed[t] = std::current_exception();
    }
  };
#ifdef _OPENMP
#pragma omp parallel num_threads(nt)
  share(omp_get_thread_num());
#else
  for (int t = 0; t < nt; ++t) share(t);                       // no OpenMP: the shares in turn
#endif
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);                          // the lowest share's first failure
}

}  // namespace ample
