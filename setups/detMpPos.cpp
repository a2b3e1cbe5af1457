//--------------------------------------------------------------------------
// detMpPos — local positions of mp x mp equally spaced points in a cell
//--------------------------------------------------------------------------
// See detMpPos.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "detMpPos.h"

namespace ample {

Eigen::MatrixX2d detMpPos(int mp) {
  Eigen::MatrixX2d mpPos(mp * mp, 2);
  for (int i = 0; i < mp; ++i)
    for (int j = 0; j < mp; ++j)
      mpPos.row(i * mp + j) << (2.0 * i + 1.0) / mp - 1.0, (2.0 * j + 1.0) / mp - 1.0;
  return mpPos;
}

}  // namespace ample
