//--------------------------------------------------------------------------
// mpData — the room of the points' basis in a basis arena (roomForBasis)
//--------------------------------------------------------------------------
// No equation: where nIN, Svp and dSvp of [AMPLE] table 3 are kept
// (basisArena.h). See mpData.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "mpData.h"

namespace ample {

// the arena the points hold, when they are its only holders: reused (its capacity
// kept); else (none yet, or a copy of a point elsewhere views it too) a new one
static std::shared_ptr<BasisArena> arenaOf(const std::vector<MaterialPoint>& mpData) {
  std::shared_ptr<BasisArena> arena = mpData.empty() ? nullptr : mpData.front().basis;
  if (!arena) return std::make_shared<BasisArena>();
  long holders = 1;                                  // this copy
  for (const MaterialPoint& mp : mpData) holders += (mp.basis == arena);
  return arena.use_count() == holders ? arena : std::make_shared<BasisArena>();
}

// v sized to n entries, all zero; storage only ever kept, never copied
template <class T>
static void zeroed(std::vector<T>& v, size_t n) {
  if (n > v.capacity()) v = std::vector<T>();        // a larger one: free the old first
  v.assign(n, T(0));
}

// point mp views its nn entries of arena from entry first on
static void viewSlice(MaterialPoint& mp, const std::shared_ptr<BasisArena>& arena, size_t first, int nn) {
  if (mp.basis != arena) mp.basis = arena;           // shares the arena's ownership
  mp.nn = nn;
  mp.nIN.viewAt(arena->nIN.data() + first);
  mp.Svp.viewAt(arena->Svp.data() + first);
  mp.dSvp.viewAt(arena->dSvp.data() + 2 * first);
}

void roomForBasis(std::vector<MaterialPoint>& mpData, const std::vector<int>& nn) {
  const std::shared_ptr<BasisArena> arena = arenaOf(mpData);
  size_t total = 0;
  for (size_t p = 0; p < mpData.size(); ++p) total += size_t(nn[p]);
  zeroed(arena->nIN, total);
  zeroed(arena->Svp, total);
  zeroed(arena->dSvp, 2 * total);
  size_t first = 0;                                  // point p's slice: [first, first + nn[p])
  for (size_t p = 0; p < mpData.size(); ++p) {
    viewSlice(mpData[p], arena, first, nn[p]);
    first += size_t(nn[p]);
  }
}

void roomForBasis(MaterialPoint& mp, int nn) {
  const std::shared_ptr<BasisArena> arena = std::make_shared<BasisArena>();
  zeroed(arena->nIN, size_t(nn));
  zeroed(arena->Svp, size_t(nn));
  zeroed(arena->dSvp, 2 * size_t(nn));
  viewSlice(mp, arena, 0, nn);
}

}  // namespace ample
