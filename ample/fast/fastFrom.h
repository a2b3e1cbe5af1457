//--------------------------------------------------------------------------
// fastFrom — the size of run from which the program's fast loops take over
//--------------------------------------------------------------------------
// elemMPinfoFast and detMPsFast hand runs of fewer points to the core's
// elemMPinfo and detMPs, so that a small run (every test, the debugger's
// recipes) steps through the core only; both give the same numbers. The size
// is that of one thread's share, pointsPerThread() (pointShares.h: 2,048, or
// AMPLE_POINTS_PER_THREAD, which the randomised runs' pairs set to 8 so that
// small runs take the fast loops and their threads too).
//--------------------------------------------------------------------------
#pragma once
#include "ample/solver/pointShares.h"

namespace ample {

inline int fastFrom() { return pointsPerThread(); }  // points

}  // namespace ample
