//--------------------------------------------------------------------------
// elemForMP — background grid cells overlapped by a material point's domain
//--------------------------------------------------------------------------
// See elemForMP.h for the rule, inputs and outputs.
//--------------------------------------------------------------------------
#include "elemForMP.h"
#include "ample/errors.h"
#include <algorithm>
#include <cmath>
#include <sstream>

namespace ample {

// a GIMP domain too large for a point's arrays (more than 9 cells or 16 nodes, e.g. 8 x 1 cells)
static std::string domainTooLarge(const Vector2d& mpC, const Vector2d& lp, const Mesh& mesh) {
  std::ostringstream msg;
  msg << "the domain of the material point at (" << mpC(0) << ", " << mpC(1) << ") has grown to lp = ("
      << lp(0) << ", " << lp(1) << ") against cells of " << mesh.h(0) << " x " << mesh.h(1)
      << ": it overlaps more than 9 cells or 16 nodes";  // what to try: whatToTry (loadSteps.cpp)
  return msg.str();
}

// the regular grid: the cells from the spacing
int elemForMP(const Mesh& mesh, const Vector2d& mpC, const Vector2d& lp,
              std::array<int, MAXE>& eIN) {
  const int nels[nD] = {mesh.nelsx, mesh.nelsy};
  int first[nD], last[nD];
  for (int i = 0; i < nD; ++i) {
    const double tol = 1e-9;  // in cell widths
    const double lo = (mpC(i) - lp(i) - mesh.origin(i)) / mesh.h(i);
    const double hi = (mpC(i) + lp(i) - mesh.origin(i)) / mesh.h(i);
    const double c = (mpC(i) - mesh.origin(i)) / mesh.h(i);  // point centre, in cells
    if (!(c > -tol && c < nels[i] + tol)) {
      std::ostringstream msg;
      msg << "material point at (" << mpC(0) << ", " << mpC(1) << ") has left the background grid ["
          << mesh.origin(0) << ", " << mesh.origin(0) + mesh.nelsx * mesh.h(0) << "] x ["
          << mesh.origin(1) << ", " << mesh.origin(1) + mesh.nelsy * mesh.h(1) << "]";
      throw RunError(msg.str(), Failure::LeftGrid);
    }
    if (!(hi - lo < 1e6))  // not finite, or so wide that the cell numbers below would overflow
      throw RunError(domainTooLarge(mpC, lp, mesh), Failure::DomainTooLarge);
    // BEGIN EXERCISE elemForMP
    if (lp(i) > 0.0) {
      first[i] = int(std::floor(lo + tol));
      last[i] = std::max(first[i], int(std::ceil(hi - tol)) - 1);
    } else {  // MPM: the cell with X_k < x <= X_k+1, the intervals SvpMPM uses (eq 23)
      // within t = 1e-9 h of a grid line the point is on it (SvpMPM uses the same t)
      int k = std::clamp(int(std::floor(c)), 0, nels[i] - 1);
      const int stride = (i == 0) ? 1 : mesh.nelsx + 1;  // node k on the grid line
      const double t = tol * mesh.h(i);
      if (mpC(i) <= mesh.coord(k * stride, i) + t && k > 0) k--;
      else if (k < nels[i] - 1 && mpC(i) > mesh.coord((k + 1) * stride, i) + t) k++;
      first[i] = last[i] = k;
    }
    // END EXERCISE
    first[i] = std::clamp(first[i], 0, nels[i] - 1);  // a domain reaching past the grid
    last[i] = std::clamp(last[i], 0, nels[i] - 1);    // edge is cut there, as in the paper
  }
  const int cx = last[0] - first[0] + 1, cy = last[1] - first[1] + 1;  // cells in x and y
  if (cx * cy > MAXE || (cx + 1) * (cy + 1) > MAXN) throw RunError(domainTooLarge(mpC, lp, mesh), Failure::DomainTooLarge);
  int ne = 0;
  for (int j = first[1]; j <= last[1]; ++j)
    for (int i = first[0]; i <= last[0]; ++i) eIN[ne++] = j * mesh.nelsx + i;
  return ne;
}

}  // namespace ample
