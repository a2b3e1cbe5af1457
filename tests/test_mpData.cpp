// Tests of the material point (ample/mpData.h): its basis in fixed-size arrays of MAXN nodes,
// the first nn its own, the rest zero; a copy of a point is a copy of its basis and of its CPDI
// domain; the size of a point (the memory of a large run).
#include "ample/elemMPinfo.h"
#include "setups/formCoord2D.h"
#include "setups/setupHelpers.h"
#include "setups/setups.h"
#include <doctest/doctest.h>

using namespace ample;

namespace {
// a block of 2 x 2 GIMP points per cell, in cells [1,3) x [1,3) of a 4 x 4 grid
std::vector<MaterialPoint> block(const Mesh& mesh) {
  Common p;
  p.mp = 2;
  p.mpType = MpType::GIMP;
  std::vector<MaterialPoint> mpData;
  fillBlock(mpData, Vector2d(1, 1), 2, 2, mesh.h, p, 1000.0);
  return mpData;
}
// the basis of a point as plain numbers: nodes, then S, then dS/dX, dS/dY of each node
std::vector<double> basisOf(const MaterialPoint& mp) {
  std::vector<double> b;
  for (int v = 0; v < mp.nn; ++v) b.insert(b.end(), {double(mp.nIN[v]), mp.Svp[v], mp.dSvp(0, v), mp.dSvp(1, v)});
  return b;
}
}  // namespace

TEST_SUITE("mpData") {
  TEST_CASE("elemMPinfo: each point's first nn entries are its basis (partition of unity), the rest zero, from step to step") {
    Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);
    std::vector<MaterialPoint> mpData = block(mesh);
    for (int step = 0; step < 3; ++step) {
      CAPTURE(step);
      elemMPinfo(mesh, mpData);
      for (const MaterialPoint& mp : mpData) {
        REQUIRE(mp.nn >= 4);
        REQUIRE(mp.nn <= MAXN);
        double S = 0;
        Vector2d dS = Vector2d::Zero();
        for (int v = 0; v < mp.nn; ++v) S += mp.Svp[v], dS += mp.dSvp.col(v);
        CHECK(std::abs(S - 1.0) <= 1e-14);                  // sum S_v = 1
        CHECK(dS.norm() <= 1e-13);                           // sum dS_v = 0
        for (int v = mp.nn; v < MAXN; ++v) CHECK((mp.nIN[v] == 0 && mp.Svp[v] == 0.0 && mp.dSvp.col(v).isZero(0.0)));
      }
      for (MaterialPoint& mp : mpData) mp.mpC += Vector2d(0.3, -0.2);  // the next step: fewer or more nodes
    }
  }

  TEST_CASE("MaterialPoint: a copy owns its basis: elemMPinfo on the points leaves a copy's basis as it was") {
    Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);
    std::vector<MaterialPoint> mpData = block(mesh);
    elemMPinfo(mesh, mpData);
    const std::vector<MaterialPoint> before = mpData;
    std::vector<std::vector<double>> basisBefore;
    for (const MaterialPoint& mp : before) basisBefore.push_back(basisOf(mp));
    for (MaterialPoint& mp : mpData) mp.mpC += Vector2d(0.3, -0.2);
    elemMPinfo(mesh, mpData);
    for (size_t p = 0; p < before.size(); ++p) CHECK(basisOf(before[p]) == basisBefore[p]);
    CHECK(basisOf(mpData[5]) != basisBefore[5]);
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

  // the point's whole state in one struct (gdb: p mpData[0]); at 2^20 points about 1 GB
  TEST_CASE("MaterialPoint: at most 1,024 bytes (the basis of 16 nodes inside, the CPDI domain on the heap)") {
    CHECK(sizeof(MaterialPoint) <= 1024);
    MESSAGE("sizeof(MaterialPoint) = ", sizeof(MaterialPoint));
  }
}
