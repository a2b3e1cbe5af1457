//--------------------------------------------------------------------------
// fastFrom — the size of run from which the program's fast loops take over
//--------------------------------------------------------------------------
// In an optimised build the program (setups/program/run.cpp) hands runs of
// fastFrom() points or more to elemMPinfoFast and detMPsFast, chosen once per
// run by the number of points only, never by the number of threads (those
// follow pointsPerThread(), pointShares.h); a Debug build (the debugger's
// recipes) and the tests of the core call elemMPinfo and detMPs themselves.
// Measured 2026-12-06, one thread, the default runs of the setups (4 to
// 2,889 points) and the compaction with nelsy = 1, 2, 4: detMPsFast took
// 0.06-0.5 times detMPs' time from 8 points up and as long at 4 points;
// elemMPinfoFast on one thread is elemMPinfo's loop. So the fast loops take
// every run of an optimised build.
//--------------------------------------------------------------------------
#pragma once

namespace ample {

inline int fastFrom() { return 1; }  // points

}  // namespace ample
