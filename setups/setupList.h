//--------------------------------------------------------------------------
// setupList.h — declarations of the setup files (one namespace per problem)
//--------------------------------------------------------------------------
// Each setup provides params() (its parameters with defaults and ranges),
// setupGrid() (mesh, boundary conditions and material points) and results()
// (the figures of its final state, e.g. the error against an analytic solution).
//--------------------------------------------------------------------------
#pragma once
#include "setups.h"

namespace ample {
namespace compaction {
Params params();
Analysis setupGrid(const Params& P);
Results results(const Analysis& an, const Params& P);
}  // namespace compaction
namespace beam {
Params params();
Analysis setupGrid(const Params& P);
Results results(const Analysis& an, const Params& P);
}  // namespace beam
namespace collapse {
Params params();
Analysis setupGrid(const Params& P);
Results results(const Analysis& an, const Params& P);
}  // namespace collapse
namespace shear {
Params params();
Analysis setupGrid(const Params& P);
Results results(const Analysis& an, const Params& P);
}  // namespace shear
namespace stretch {
Params params();
Analysis setupGrid(const Params& P);
Results results(const Analysis& an, const Params& P);
}  // namespace stretch
}  // namespace ample
