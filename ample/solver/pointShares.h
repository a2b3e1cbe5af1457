//--------------------------------------------------------------------------
// pointShares — the point loops of detMPs and elemMPinfo on several threads
//--------------------------------------------------------------------------
// Two cores (OpenMP); no equation of the papers: how the loop over points
// is split, not what it computes.
// pointThreads(np): 1 without OpenMP (CMake option AMPLE_OPENMP) or for fewer
//   than pointsPerThread() points a thread, else OMP_NUM_THREADS or the cores,
//   at most np / pointsPerThread(). The threads do not change the numbers
//   (detMPs: each thread owns nodes; elemMPinfo: each point its own).
// pointsPerThread(): 2048, or the environment's AMPLE_POINTS_PER_THREAD (a whole
//   number >= 1; the tests set it low so that small runs take the threaded path).
// forPointShares(np, nt, work): thread t = 0 .. nt-1 runs work(t, begin, end)
//   on the contiguous share [np t / nt, np (t+1) / nt) of the points. A share
//   that throws stops there; after all shares the exception of the lowest
//   share is rethrown (the first failing point in point order, as serially).
//   nt = 1 runs work(0, 0, np) on the calling thread.
// Inputs:  np points · nt threads · work
// Outputs: what work writes (each share its own points, or a buffer of its own)
// Tests:   tests/test_detMPs.cpp (threaded point loop), tests/test_elemMPinfo.cpp
//--------------------------------------------------------------------------
#pragma once
#include <functional>

namespace ample {

int pointsPerThread();
int pointThreads(int np);
void forPointShares(int np, int nt, const std::function<void(int t, int begin, int end)>& work);

}  // namespace ample
