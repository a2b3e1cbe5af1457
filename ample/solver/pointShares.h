//--------------------------------------------------------------------------
// pointShares — the point loops of detMPs and elemMPinfo on several threads
//--------------------------------------------------------------------------
// Two cores (OpenMP); no equation of the papers: how the loop over points
// is split, not what it computes.
// pointThreads(np): 1 without OpenMP (CMake option AMPLE_OPENMP) or for fewer
//   than 2048 points a thread (small runs stay serial, bit for bit), else
//   OMP_NUM_THREADS or the cores, at most np / 2048.
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

int pointThreads(int np);
void forPointShares(int np, int nt, const std::function<void(int t, int begin, int end)>& work);

}  // namespace ample
