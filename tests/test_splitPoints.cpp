// Tests of the split= remedy (ample/remedies/splitPoints.cpp): a stretched GIMP point is cut
// into halves that conserve mass and volume exactly and tile the parent's domain; a state
// with no stretched point, or the remedy off, is left bit for bit; a run that needs no split
// is the same with the remedy on and off.
#include "ample/remedies/splitPoints.h"
#include "testProblems.h"
#include <doctest/doctest.h>
#include <cstring>

using namespace ample;
using namespace ample::testing;

namespace {
// the fields a split touches or copies, compared exactly
bool samePoint(const MaterialPoint& a, const MaterialPoint& b) {
  return a.mpC == b.mpC && a.X0 == b.X0 && a.lp == b.lp && a.lp0 == b.lp0 && a.vp == b.vp &&
         a.vp0 == b.vp0 && a.mpM == b.mpM && a.fp == b.fp && a.F == b.F && a.Fn == b.Fn &&
         a.sig == b.sig && a.epsE == b.epsE && a.epsEn == b.epsEn && a.u == b.u;
}
}  // namespace

TEST_SUITE("splitPoints") {
  TEST_CASE("splitPoints: a point stretched to lp = 0.8 h is cut once into halves that tile it") {
    Analysis an = smallBlock(MpType::GIMP, CmType::VonMises, 2);   // h = 1 m, lp0 = 0.25 m
    prestrain(an.mpData, 7);
    an.mpData[1].lp(0) = 0.8;                                       // stretched in x
    an.mpData[1].fp = Vector2d(3, -5);
    const MaterialPoint parent = an.mpData[1];
    const size_t n = an.mpData.size();
    REQUIRE(splitPoints(an.mesh, 0.5, an.mpData) == 1);
    REQUIRE(an.mpData.size() == n + 1);
    const MaterialPoint &lo = an.mpData[1], &hi = an.mpData[n];
    CHECK(lo.mpM + hi.mpM == parent.mpM);                           // exactly
    CHECK(lo.vp + hi.vp == parent.vp);
    CHECK(lo.vp0 + hi.vp0 == parent.vp0);
    CHECK(lo.fp + hi.fp == parent.fp);
    CHECK(lo.lp(0) == 0.4);
    CHECK(hi.lp(0) == 0.4);
    CHECK(lo.lp(1) == parent.lp(1));
    CHECK(lo.mpC(0) - lo.lp(0) == parent.mpC(0) - parent.lp(0));   // the halves tile the domain
    CHECK(hi.mpC(0) + hi.lp(0) == parent.mpC(0) + parent.lp(0));
    CHECK(lo.mpC(0) + lo.lp(0) == hi.mpC(0) - hi.lp(0));
    CHECK(lo.mpC(1) == parent.mpC(1));
    CHECK(hi.F == parent.F);                                        // the state is the parent's
    CHECK(hi.Fn == parent.Fn);
    CHECK(hi.epsEn == parent.epsEn);
    CHECK(hi.sig == parent.sig);
    CHECK(lo.X0(0) + hi.X0(0) == 2 * parent.X0(0));                 // origins straddle X0
    CHECK(hi.u == hi.mpC - hi.X0);
  }

  TEST_CASE("splitPoints: a point with lp = 2.1 h is cut until every piece is under half a cell") {
    Analysis an = smallBlock(MpType::GIMP, CmType::Elastic, 1);
    REQUIRE(an.mpData.size() == 4);
    an.mpData[2].lp(1) = 2.1;
    double M = 0, V = 0;
    for (const MaterialPoint& mp : an.mpData) M += mp.mpM, V += mp.vp;
    REQUIRE(splitPoints(an.mesh, 0.5, an.mpData) == 7);             // 1 -> 8 pieces of lp 0.2625
    REQUIRE(an.mpData.size() == 11);
    double M1 = 0, V1 = 0, ymin = 1e9, ymax = -1e9;
    for (const MaterialPoint& mp : an.mpData) {
      M1 += mp.mpM, V1 += mp.vp;
      CHECK(mp.lp(1) <= 0.5);
      if (mp.X0(0) == an.mpData[2].X0(0)) ymin = std::min(ymin, mp.mpC(1) - mp.lp(1)),
                                          ymax = std::max(ymax, mp.mpC(1) + mp.lp(1));
    }
    CHECK(M1 == doctest::Approx(M).epsilon(1e-15));                 // eighths: exact per piece
    CHECK(V1 == doctest::Approx(V).epsilon(1e-15));
    CHECK(ymax - ymin == doctest::Approx(4.2).epsilon(1e-15));
  }

  TEST_CASE("splitPoints: no point over the threshold, or the remedy off, changes nothing") {
    Analysis an = smallBlock(MpType::GIMP, CmType::VonMises, 2);
    prestrain(an.mpData, 3);
    an.mpData[0].lp(0) = 0.5;                                       // at the threshold: kept
    const std::vector<MaterialPoint> before = an.mpData;
    CHECK(splitPoints(an.mesh, 0.5, an.mpData) == 0);
    an.mpData[3].lp(1) = 3.0;
    std::vector<MaterialPoint> stretched = an.mpData;
    CHECK(splitPoints(an.mesh, 0, an.mpData) == 0);                 // off
    REQUIRE(an.mpData.size() == before.size());
    for (size_t p = 0; p < before.size(); ++p) CHECK(samePoint(an.mpData[p], stretched[p]));
    an.mpData[3].lp(1) = before[3].lp(1);
    for (size_t p = 0; p < before.size(); ++p) CHECK(samePoint(an.mpData[p], before[p]));
  }

  TEST_CASE("splitPoints: a collapse that needs no split is the same bit for bit with split=0.5") {
    RunLog off, on;
    const Analysis a = runSetup("collapse", {{"lstps", 10}}, off);
    const Analysis b = runSetup("collapse", {{"lstps", 10}, {"split", 0.5}}, on);
    CHECK(on.splits == 0);
    REQUIRE(a.mpData.size() == b.mpData.size());
    for (size_t p = 0; p < a.mpData.size(); ++p) CHECK(samePoint(a.mpData[p], b.mpData[p]));
    CHECK(off.totalNRit == on.totalNRit);
  }
}
