// Tests of pointShares (the point loops on several threads) and of the threaded
// elemMPinfo: the shares cover every point once, in contiguous ranges; a failure
// is reported for the first failing point in point order; the basis of 4,096
// scattered GIMP and CPDI points on two threads equals the serial one bit for bit,
// on the grid and (MPM and CPDI points) on a general mesh.
#include "ample/cpdi/elemMPinfoCPDI.h"
#include "ample/fast/elemMPinfoFast.h"
#include "ample/errors.h"
#include "ample/meshes/elemMPinfoMesh.h"
#include "ample/meshes/generalMesh.h"
#include "setups/formCoord2D.h"
#include "ample/solver/pointShares.h"
#include "setups/setupHelpers.h"
#include "setups/setups.h"
#include <doctest/doctest.h>
#include <cstdlib>
#include <random>
#include <string>
#ifdef _OPENMP
#include <omp.h>
#endif

using namespace ample;

namespace {
// 4,096 points of 16 x 16 cells (4 x 4 each), moved by up to a quarter cell and
// with domains from 0.3 to 1.2 of their original half-lengths: every point links
// its own set of 4 to 16 nodes; every 7th point is CPDI2 with skewed corners
std::vector<MaterialPoint> scatteredPoints(const Mesh& mesh) {
  Common P;
  P.mp = 4;
  P.mpType = MpType::GIMP;
  P.E = 1e6;
  P.nu = 0.3;
  std::vector<MaterialPoint> mpData;
  fillBlock(mpData, Vector2d(2, 2), 16, 16, mesh.h, P, 1000.0);
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0), s(0.3, 1.2);
  for (size_t p = 0; p < mpData.size(); ++p) {
    MaterialPoint& mp = mpData[p];
    mp.mpC += 0.25 * mesh.h.cwiseProduct(Vector2d(u(gen), u(gen)));
    mp.lp = mp.lp0.cwiseProduct(Vector2d(s(gen), s(gen)));
    if (p % 7 == 0) {
      mp.mpType = MpType::CPDI2;
      mp.cpdi = CpdiDomain();                 // a domain of its own: its corners
      for (int c = 0; c < 4; ++c)
        mp.cpdi->xc.col(c) = mp.mpC + Vector2d(c == 1 || c == 2 ? 1 : -1, c >= 2 ? 1 : -1).cwiseProduct(mp.lp) +
                       0.2 * mp.lp.cwiseProduct(Vector2d(u(gen), u(gen)));
    }
  }
  return mpData;
}
// the 20 x 20 grid as a general quadrilateral mesh, its interior nodes moved by up to
// 0.15 h (the cells stay convex), and scatteredPoints in it as standard MPM points
// (GIMP needs the grid) but for the CPDI2 ones
Mesh jitteredMesh(std::vector<MaterialPoint>& mpData) {
  const Mesh grid = formCoord2D(20, 20, 20.0, 20.0);
  Eigen::MatrixX2d x = grid.coord;
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(-0.15, 0.15);
  for (int n = 0; n < grid.nodes(); ++n)
    if (x(n, 0) > 0 && x(n, 0) < 20 && x(n, 1) > 0 && x(n, 1) < 20) x.row(n) += Eigen::RowVector2d(u(gen), u(gen));
  mpData = scatteredPoints(grid);
  for (MaterialPoint& mp : mpData)
    if (!isCPDI(mp)) mp.mpType = MpType::MPM, mp.lp = mp.lp0 = Vector2d::Zero();
  return generalMesh(x, grid.etpl);
}
// the points of a and b have the same cells, nodes and basis, bit for bit
int sameBasis(const std::vector<MaterialPoint>& a, const std::vector<MaterialPoint>& b) {
  int same = 0;
  for (size_t p = 0; p < a.size(); ++p)
    same += a[p].nn == b[p].nn && a[p].ne == b[p].ne && a[p].eIN == b[p].eIN &&
            std::equal(a[p].nIN.begin(), a[p].nIN.begin() + a[p].nn, b[p].nIN.begin()) &&
            std::equal(a[p].Svp.begin(), a[p].Svp.begin() + a[p].nn, b[p].Svp.begin()) &&
            a[p].dSvp.leftCols(a[p].nn) == b[p].dSvp.leftCols(b[p].nn);
  return same;
}
}  // namespace

TEST_SUITE("pointShares") {
  TEST_CASE("forPointShares: nt contiguous shares cover every point exactly once, share t from np t/nt up to np (t+1)/nt") {
    for (int nt : {1, 2, 3}) {
      const int np = 10007;
      std::vector<int> hits(np, 0), owner(np, -1);
      forPointShares(np, nt, [&](int t, int begin, int end) {
        CHECK(begin == int(long(np) * t / nt));
        CHECK(end == int(long(np) * (t + 1) / nt));
        for (int p = begin; p < end; ++p) {
          hits[p]++;
          owner[p] = t;
        }
      });
      int once = 0, ordered = 1;
      for (int p = 0; p < np; ++p) {
        once += hits[p] == 1;
        if (p > 0 && owner[p] < owner[p - 1]) ordered = 0;
      }
      CHECK(once == np);
      CHECK(ordered == 1);
      CHECK(owner[np - 1] == nt - 1);
    }
  }

  TEST_CASE("forPointShares: a failure in two shares is reported as the lower share's (the first in point order)") {
    std::string what;
    try {
      forPointShares(1000, 2, [&](int t, int begin, int) {
        throw RunError("share " + std::to_string(t) + " from point " + std::to_string(begin));
      });
    } catch (const RunError& e) {
      what = e.what();
    }
    CHECK(what == "share 0 from point 0");
  }

  TEST_CASE("pointThreads: serial below pointsPerThread() points a thread (2,048 unless AMPLE_POINTS_PER_THREAD)") {
    const char* env = std::getenv("AMPLE_POINTS_PER_THREAD");
    if (!env) CHECK(pointsPerThread() == 2048);
    const int least = pointsPerThread();
    CHECK(pointThreads(0) == 1);
    CHECK(pointThreads(2 * least - 1) == 1);
#ifdef _OPENMP
    const int before = omp_get_max_threads();
    omp_set_num_threads(2);
    CHECK(pointThreads(2 * least) == 2);
    CHECK(pointThreads(1 << 30) == 2);
    omp_set_num_threads(before);
#endif
  }

  TEST_CASE("elemMPinfoFast: the basis of 4,096 scattered GIMP and CPDI2 points on two threads equals the serial loop's (elemMPinfoCPDI) bit for bit") {
#ifndef _OPENMP
    MESSAGE("built without AMPLE_OPENMP: elemMPinfoFast is serial, nothing to compare");
#else
    const int before = omp_get_max_threads();
    Mesh mesh[2] = {formCoord2D(20, 20, 20.0, 20.0), formCoord2D(20, 20, 20.0, 20.0)};
    std::vector<MaterialPoint> mps[2] = {scatteredPoints(mesh[0]), scatteredPoints(mesh[0])};
    elemMPinfoCPDI(mesh[0], mps[0]);                  // the serial loop of these points
    omp_set_num_threads(2);
    REQUIRE(pointThreads(4096) == std::min(2, 4096 / pointsPerThread()));
    elemMPinfoFast(mesh[1], mps[1]);
    omp_set_num_threads(before);
    REQUIRE(mps[0].size() == 4096);
    int same = 0, nnMin = MAXN, nnMax = 0;
    for (size_t p = 0; p < mps[0].size(); ++p) {
      const MaterialPoint &a = mps[0][p], &b = mps[1][p];
      same += a.nn == b.nn && a.ne == b.ne && a.eIN == b.eIN &&
              std::equal(a.nIN.begin(), a.nIN.begin() + a.nn, b.nIN.begin()) &&
              std::equal(a.Svp.begin(), a.Svp.begin() + a.nn, b.Svp.begin()) &&
              a.dSvp.leftCols(a.nn) == b.dSvp.leftCols(b.nn);
      nnMin = std::min(nnMin, a.nn);
      nnMax = std::max(nnMax, a.nn);
    }
    CHECK(same == 4096);
    CHECK(mesh[0].eInA == mesh[1].eInA);
    CHECK(nnMin < nnMax);                             // the points do link different nodes
#endif
  }

  TEST_CASE("elemMPinfoFast: on two threads a point that left the grid is named as the serial loop names it (the first such point)") {
    Mesh mesh = formCoord2D(20, 20, 20.0, 20.0);
    std::vector<MaterialPoint> mpData = scatteredPoints(mesh);
    mpData[3000].mpC = Vector2d(25.0, 5.0);           // past x = 20, in the second share
    mpData[3500].mpC = Vector2d(-1.0, 5.0);
    std::string what[2];
#ifdef _OPENMP
    const int before = omp_get_max_threads();
#endif
    for (int run = 0; run < 2; ++run) {
#ifdef _OPENMP
      omp_set_num_threads(run + 1);
#endif
      try {
        if (run == 0) elemMPinfoCPDI(mesh, mpData);
        else elemMPinfoFast(mesh, mpData);
      } catch (const RunError& e) {
        what[run] = e.what();
      }
    }
#ifdef _OPENMP
    omp_set_num_threads(before);
#endif
    CHECK(what[0].rfind("point 3000: ", 0) == 0);
    CHECK(what[1] == what[0]);
  }

  TEST_CASE("elemMPinfoFast: on a general mesh, 4,096 MPM points (and with CPDI2 points) on two threads equal elemMPinfoMesh's (elemMPinfoCPDI's) bit for bit, also keeping their cells (FE mode)") {
#ifndef _OPENMP
    MESSAGE("built without AMPLE_OPENMP: elemMPinfoFast is serial, nothing to compare");
#else
    const int before = omp_get_max_threads();
    for (bool cpdi : {false, true}) {
      CAPTURE(cpdi);
      std::vector<MaterialPoint> mps[2];
      Mesh mesh[2] = {jitteredMesh(mps[0]), jitteredMesh(mps[1])};
      if (!cpdi)
        for (auto& pts : mps)
          for (MaterialPoint& mp : pts)
            if (isCPDI(mp)) mp.mpType = MpType::MPM, mp.cpdi = Indirect<CpdiDomain>(), mp.lp = Vector2d::Zero();
      for (bool keepCells : {false, true}) {        // the second pass keeps the cells of the first
        if (cpdi) elemMPinfoCPDI(mesh[0], mps[0], keepCells);
        else elemMPinfoMesh(mesh[0], mps[0], keepCells);
        omp_set_num_threads(2);
        REQUIRE(pointThreads(4096) == std::min(2, 4096 / pointsPerThread()));
        elemMPinfoFast(mesh[1], mps[1], keepCells);
        omp_set_num_threads(before);
        REQUIRE(mps[0].size() == 4096);
        CHECK(sameBasis(mps[0], mps[1]) == 4096);
        CHECK(mesh[0].eInA == mesh[1].eInA);
      }
      int nnMax = 0;
      for (const MaterialPoint& mp : mps[0]) nnMax = std::max(nnMax, mp.nn);
      CHECK(nnMax == (cpdi ? 9 : 4));               // CPDI2 domains reach the next cells
    }
#endif
  }
}
