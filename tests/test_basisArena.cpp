// Tests of the basis arena (ample/basisArena.h, roomForBasis in ample/mpData.h): each point
// views its own nn entries, the slices follow one another in point order; elemMPinfo keeps
// one arena from step to step, and a copy of the points keeps the basis it had; a copy of a
// CPDI domain is a copy; the views read as the paper's arrays (2 x nn column-major dSvp).
#include "ample/elemMPinfo.h"
#include "ample/meshes/formCoord2D.h"
#include "setups/setupHelpers.h"
#include "setups/setups.h"
#include <doctest/doctest.h>

using namespace ample;

namespace {
// a block of 2 x 2 GIMP points per cell, in cells [1,3) x [1,3) of a 4 x 4 grid
std::vector<MaterialPoint> block(const Mesh& mesh) {
  Params P = commonParams(1);
  setDefault(P, "mp", 2);
  setDefault(P, "mpType", 2);
  std::vector<MaterialPoint> mpData;
  fillBlock(mpData, Vector2d(1, 1), 2, 2, mesh.h, P, 1000.0);
  return mpData;
}
// the basis of a point as plain numbers: nodes, then S, then dS/dX, dS/dY of each node
std::vector<double> basisOf(const MaterialPoint& mp) {
  std::vector<double> b;
  for (int v = 0; v < mp.nn; ++v) b.insert(b.end(), {double(mp.nIN[v]), mp.Svp[v], mp.dSvp(0, v), mp.dSvp(1, v)});
  return b;
}
}  // namespace

TEST_SUITE("basisArena") {
  TEST_CASE("roomForBasis: point p gets nn[p] zeroed entries right after point p-1's, nn set; writes stay in the slice") {
    std::vector<MaterialPoint> mpData(3);
    const std::vector<int> nn = {4, 6, 9};
    roomForBasis(mpData, nn);
    const BasisArena& arena = *mpData[0].basis;
    CHECK(arena.nIN.size() == 19);
    CHECK(arena.Svp.size() == 19);
    CHECK(arena.dSvp.size() == 38);
    for (int p = 0, first = 0; p < 3; first += nn[p], ++p) {
      CAPTURE(p);
      const MaterialPoint& mp = mpData[p];
      CHECK(mp.basis == mpData[0].basis);                  // one arena for all
      CHECK(mp.nn == nn[p]);
      CHECK(mp.nIN.data() == arena.nIN.data() + first);    // contiguous, in point order
      CHECK(mp.Svp.data() == arena.Svp.data() + first);
      CHECK(mp.dSvp.data() == arena.dSvp.data() + 2 * first);
      for (int v = 0; v < mp.nn; ++v) CHECK((mp.nIN[v] == 0 && mp.Svp[v] == 0.0 && mp.dSvp.col(v).isZero(0.0)));
    }
    for (int v = 0; v < 6; ++v) {                          // fill point 1 only
      mpData[1].nIN[v] = 10 + v;
      mpData[1].Svp[v] = 0.5 + v;
      mpData[1].dSvp(0, v) = -v;
      mpData[1].dSvp(1, v) = 2.0 * v;
    }
    CHECK(basisOf(mpData[0]) == std::vector<double>(16, 0.0));  // its neighbours untouched
    CHECK(basisOf(mpData[2]) == std::vector<double>(36, 0.0));
    CHECK(basisOf(mpData[1])[4 * 5 + 3] == 10.0);
  }

  TEST_CASE("roomForBasis: dSvp is 2 x nn column-major: dSvp(j, v) = col(v)(j) = leftCols(nn)(j, v)") {
    MaterialPoint mp;
    roomForBasis(mp, 3);
    for (int v = 0; v < 3; ++v) mp.dSvp.col(v) << 1.0 + v, 10.0 + v;
    const MaterialPoint& c = mp;                           // read as a const point
    Eigen::Matrix<double, 2, 3> expected;
    expected << 1, 2, 3, 10, 11, 12;
    CHECK(c.dSvp.leftCols(c.nn) == expected);
    CHECK(c.dSvp(1, 2) == 12.0);
    CHECK(c.dSvp.data()[3] == 11.0);                       // (x, y) of node 1: entries 2, 3
    const Eigen::Matrix2d iF = Eigen::Vector2d(2, -1).asDiagonal();
    const Eigen::Matrix<double, 2, 3> mapped = iF.transpose() * c.dSvp.leftCols(c.nn);  // eq 18's product
    CHECK(mapped(0, 1) == 4.0);
    CHECK(mapped(1, 2) == -12.0);
  }

  TEST_CASE("elemMPinfo: the arena is kept from step to step (its capacity reused); a copy of the points keeps its basis") {
    Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);
    std::vector<MaterialPoint> mpData = block(mesh);
    elemMPinfo(mesh, mpData);
    const BasisArena* arena = mpData[0].basis.get();
    size_t slots = 0;
    for (const MaterialPoint& mp : mpData) {
      CHECK(mp.basis.get() == arena);
      slots += size_t(mp.nn);                              // GIMP points drop no node
    }
    CHECK(arena->nIN.size() == slots);
    CHECK(mpData[0].basis.use_count() == long(mpData.size()));  // the points, no one else
    const std::vector<MaterialPoint> before = mpData;      // copies view the same slices
    std::vector<std::vector<double>> basisBefore;
    for (const MaterialPoint& mp : before) basisBefore.push_back(basisOf(mp));

    for (MaterialPoint& mp : mpData) mp.mpC += Vector2d(0.3, -0.2);  // the next step
    elemMPinfo(mesh, mpData);
    CHECK(mpData[0].basis.get() != arena);                 // `before` holds the old arena:
    for (size_t p = 0; p < before.size(); ++p)             // its basis is still that of before
      CHECK(basisOf(before[p]) == basisBefore[p]);
    CHECK(basisOf(mpData[5]) != basisBefore[5]);           // the points have their new one

    const BasisArena* second = mpData[0].basis.get();      // no copy now: the same arena again
    const int* nodes = second->nIN.data();
    for (size_t p = 0; p < mpData.size(); ++p) mpData[p].mpC = before[p].mpC;  // back again
    elemMPinfo(mesh, mpData);
    CHECK(mpData[0].basis.get() == second);
    CHECK(second->nIN.data() == nodes);                    // the same storage, not reallocated
    for (size_t p = 0; p < before.size(); ++p) CHECK(basisOf(mpData[p]) == basisBefore[p]);
  }

  TEST_CASE("elemMPinfo: points added after a step (split, a setup) get a slice with the others at the next call") {
    Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);
    std::vector<MaterialPoint> mpData = block(mesh);
    elemMPinfo(mesh, mpData);
    MaterialPoint extra = mpData[3];                       // a copy: the same slice as point 3
    CHECK(extra.nIN.data() == mpData[3].nIN.data());
    extra.mpC = Vector2d(2.9, 2.9);
    mpData.push_back(extra);
    elemMPinfo(mesh, mpData);
    const MaterialPoint& last = mpData.back();
    CHECK(last.basis == mpData[0].basis);
    CHECK(last.nIN.data() == mpData[mpData.size() - 2].nIN.data() + mpData[mpData.size() - 2].nn);
    CHECK(last.nIN.data() != mpData[3].nIN.data());
    double S = 0;
    for (int v = 0; v < last.nn; ++v) S += last.Svp[v];
    CHECK(std::abs(S - 1.0) <= 1e-14);
  }

  TEST_CASE("Indirect: a CPDI point's copy owns a copy of its domain; MPM and GIMP points have none") {
    MaterialPoint a;
    CHECK_FALSE(a.cpdi);
    a.mpType = MpType::CPDI1;
    a.cpdi = CpdiDomain();
    a.cpdi->st0 = Eigen::Matrix2d::Identity();
    MaterialPoint b = a;                                   // copy construction
    b.cpdi->st0(0, 1) = 0.5;
    CHECK(a.cpdi->st0(0, 1) == 0.0);
    CHECK(b.cpdi.operator->() != a.cpdi.operator->());
    MaterialPoint c;
    c = b;                                                 // copy assignment into an empty one
    CHECK(c.cpdi->st0(0, 1) == 0.5);
    c = MaterialPoint();                                   // and back to none
    CHECK_FALSE(c.cpdi);
    Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);
    for (const MaterialPoint& mp : block(mesh)) CHECK_FALSE(mp.cpdi);  // GIMP: no domain kept
  }

  TEST_CASE("MaterialPoint: 544 bytes, the basis in the arena and the CPDI domain on the heap (1,088 with both inside)") {
    CHECK(sizeof(MaterialPoint) <= 544);
  }
}
