//--------------------------------------------------------------------------
// fastFrom — the size of run from which the program's fast loops take over
//--------------------------------------------------------------------------
// elemMPinfoFast and detMPsFast hand runs of fewer points to the core's
// elemMPinfo and detMPs, so that a small run (every test, the debugger's
// recipes) steps through the core only; both give the same numbers.
//--------------------------------------------------------------------------
#pragma once

namespace ample {

constexpr int fastFrom = 2048;  // points

}  // namespace ample
