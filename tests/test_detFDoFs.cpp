// Tests of detFDoFs ([AMPLE] sec 4, sec 5.3): the free degrees of freedom are
// those of the nodes of active cells, less the constrained ones, ascending.
// With the points (the analysis): the nodes linked to a point, less the redundant
// dofs of nodes that only one CPDI corner reaches, the redundant
// lone nodes of a GIMP point alone in a row of cells (Kt(fd,fd) of full rank, the
// same on one and two threads), and the
// elemMPinfo rule that a node with zero basis value and gradient is not linked.
#include "ample/detFDoFs.h"
#include "ample/remedies/loneNodes.h"
#include "ample/detMPs.h"
#include "ample/cpdi/elemMPinfoCPDI.h"
#include "setups/formCoord2D.h"
#include "testProblems.h"
#include <doctest/doctest.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include <Eigen/LU>
#include <algorithm>
#include <array>

using namespace ample;

TEST_SUITE("detFDoFs") {
  TEST_CASE("detFDoFs: all dofs of a fully active grid without constraints") {
    Mesh mesh = formCoord2D(2, 1, 2.0, 1.0);  // 6 nodes, 12 dofs
    mesh.eInA.assign(mesh.nels(), 1);
    std::vector<int> all(12);
    for (int d = 0; d < 12; ++d) all[d] = d;
    CHECK(activeCellDoFs(mesh) == all);
  }
  TEST_CASE("detFDoFs: only nodes of active cells / minus the bc dofs / ascending") {
    Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);  // 5 nodes per row
    mesh.eInA.assign(mesh.nels(), 0);
    mesh.eInA[5] = mesh.eInA[6] = 1;           // nodes 6 7 8 11 12 13
    mesh.bc = {{dof(7, 0), 0.0}, {dof(12, 1), 0.1}, {dof(0, 1), 0.0}};  // node 0 is inactive
    const std::vector<int> expected = {dof(6, 0),  dof(6, 1),  /* 7x held */ dof(7, 1),
                                       dof(8, 0),  dof(8, 1),  dof(11, 0), dof(11, 1),
                                       dof(12, 0), /* 12y held */ dof(13, 0), dof(13, 1)};
    CHECK(activeCellDoFs(mesh) == expected);
  }
  TEST_CASE("detFDoFs: separate active regions / shared nodes counted once") {
    Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);
    mesh.eInA.assign(mesh.nels(), 0);
    mesh.eInA[0] = mesh.eInA[5] = mesh.eInA[15] = 1;  // cells 0 and 5 share node 6
    const std::vector<int> fd = activeCellDoFs(mesh);
    CHECK(fd.size() == 2 * (4 + 3 + 4));  // nodes 0 1 5 6 | 7 11 12 | 18 19 23 24
    CHECK(std::is_sorted(fd.begin(), fd.end()));
    CHECK(std::adjacent_find(fd.begin(), fd.end()) == fd.end());
    for (int n : {0, 1, 5, 6, 7, 11, 12, 18, 19, 23, 24})
      for (int i = 0; i < nD; ++i) CHECK(std::binary_search(fd.begin(), fd.end(), dof(n, i)));
  }
  TEST_CASE("detFDoFs: the dofs of the nodes linked to a point, less the bc dofs, ascending (points linked by hand)") {
    Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);  // 5 nodes per row, node = 5 row + column
    std::vector<MaterialPoint> pts(3);
    const std::array<int, 4> nodes[3] = {{6, 7, 11, 12}, {7, 8, 12, 13}, {18, 19, 23, 24}};
    for (int p = 0; p < 3; ++p) {      // standard MPM points, each linked to one cell's nodes
      pts[p].mpType = MpType::MPM;
      pts[p].nn = 4;
      for (int v = 0; v < 4; ++v) pts[p].nIN[v] = nodes[p][v];
    }
    mesh.bc = {{dof(7, 0), 0.0}, {dof(23, 1), 0.1}, {dof(0, 1), 0.0}};  // node 0 is not linked
    const std::vector<int> expected = {dof(6, 0),  dof(6, 1),  /* 7x held */ dof(7, 1),
                                       dof(8, 0),  dof(8, 1),  dof(11, 0), dof(11, 1),
                                       dof(12, 0), dof(12, 1), dof(13, 0), dof(13, 1),
                                       dof(18, 0), dof(18, 1), dof(19, 0), dof(19, 1),
                                       dof(23, 0), /* 23y held */ dof(24, 0), dof(24, 1)};
    CHECK(detFDoFs(mesh, pts) == expected);
    CHECK(detFDoFs(mesh, {}) == std::vector<int>{});  // no point: nothing to solve for
  }
}

namespace {
bool linked(const MaterialPoint& mp, int node) {
  return std::find(mp.nIN.begin(), mp.nIN.begin() + mp.nn, node) != mp.nIN.begin() + mp.nn;
}
bool has(const std::vector<int>& fd, int d) { return std::binary_search(fd.begin(), fd.end(), d); }

// rank of Kt(fd, fd), dense
int rankOf(const SpMat& Kt, const std::vector<int>& fd) {
  const Eigen::MatrixXd K = Eigen::MatrixXd(Kt);
  Eigen::MatrixXd Kf(fd.size(), fd.size());
  for (size_t i = 0; i < fd.size(); ++i)
    for (size_t j = 0; j < fd.size(); ++j) Kf(i, j) = K(fd[i], fd[j]);
  Eigen::FullPivLU<Eigen::MatrixXd> lu(Kf);
  lu.setThreshold(1e-10);
  return int(lu.rank());
}
}  // namespace

TEST_SUITE("elemMPinfo") {
  TEST_CASE("elemMPinfoCPDI: a CPDI corner on the far edge of its cell does not link the nodes with zero basis there") {
    // the collapse toe: a CPDI2 point on the base (y = 0) whose lower-right corner
    // (2.1, 0) is the only corner in cell 2 = [2,3] x [0,1]; node 8 at (3, 1) has
    // N = 0.1 x 0 = 0 there, so S = 0 and dS = 0: linked, it was an empty column
    Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);  // 5 nodes per row
    for (MpType t : {MpType::CPDI2, MpType::CPDI1}) {
      CAPTURE(int(t));
      std::vector<MaterialPoint> mpData(1);
      MaterialPoint& mp = mpData[0];
      mp.mpType = t;
      mp.cpdi = CpdiDomain();
      mp.cpdi->xc << 1.2, 2.1, 1.9, 1.0,   // x of the corners, anticlockwise from lower left
               0.0, 0.0, 0.6, 0.6;   // y
      if (t == MpType::CPDI1) {      // a parallelogram with the same lower edge
        mp.cpdi->st << 0.9, -0.2, 0.0, 0.6;  // columns s, t
        mp.mpC = Vector2d(1.55, 0.3);
      } else {
        mp.mpC = mp.cpdi->xc.rowwise().mean();
      }
      elemMPinfoCPDI(mesh, mpData);
      CHECK(mp.ne == 2);             // cells 1 and 2
      CHECK(linked(mp, 3));          // (3, 0): N = 0.1 at the corner
      CHECK_FALSE(linked(mp, 8));    // (3, 1): N = 0 at every corner
      double S = 0;
      for (int v = 0; v < mp.nn; ++v) {
        CHECK((mp.Svp[v] != 0.0 || !mp.dSvp.col(v).isZero(0.0)));
        S += mp.Svp[v];
      }
      CHECK(std::abs(S - 1.0) <= 1e-13);  // the dropped node carried nothing
      CHECK(has(detFDoFs(mesh, mpData), dof(3, 0)));
      CHECK_FALSE(has(detFDoFs(mesh, mpData), dof(8, 0)));  // cell 2 is active, node 8 not free
      CHECK(has(activeCellDoFs(mesh), dof(8, 0)));          // the active-cell rule keeps it
    }
  }
}

TEST_SUITE("detFDoFs") {
  TEST_CASE("detFDoFs: nodes that one CPDI corner alone reaches keep one free dof per direction") {
    // a block of 2 x 2 CPDI points per cell in cells [1,3) x [1,3), rollers on
    // y = 1; the top-right point's domain gets the corners (2.3, 2.2) (3, 2.5)
    // (3.2, 3.3) (2.5, 3), a parallelogram: only corner 2 enters the empty cell 15 =
    // [3,4] x [3,4], so nodes (4,3), (4,4), (3,4) are linked through it alone, their
    // gradients are parallel and Kt over all linked dofs has 4 zero-energy modes
    for (MpType t : {MpType::CPDI2, MpType::CPDI1}) {
      CAPTURE(int(t));
      Analysis an = testing::smallBlock(t, CmType::Elastic, 2);
      size_t top = 0;
      for (size_t p = 0; p < an.mpData.size(); ++p)
        if ((an.mpData[p].mpC - Vector2d(2.75, 2.75)).norm() < 1e-12) top = p;
      MaterialPoint& mp = an.mpData[top];
      REQUIRE((mp.mpC - Vector2d(2.75, 2.75)).norm() < 1e-12);
      mp.cpdi->xc << 2.3, 3.0, 3.2, 2.5,
               2.2, 2.5, 3.3, 3.0;
      mp.cpdi->st << 0.7, 0.2,   // columns s = x1 - x0, t = x3 - x0; centre (2.75, 2.75)
               0.3, 0.8;
      for (int n = 0; n < an.mesh.nodes(); ++n)
        if (std::abs(an.mesh.coord(n, 1) - 1.0) < 1e-12)
          for (int i = 0; i < nD; ++i) an.mesh.bc.push_back({dof(n, i), 0.0});
      elemMPinfoCPDI(an.mesh, an.mpData);
      const int n43 = 3 * 5 + 4, n44 = 4 * 5 + 4, n34 = 4 * 5 + 3;  // nodes (4,3) (4,4) (3,4)
      for (int n : {n43, n44, n34}) CHECK(linked(mp, n));
      const std::vector<int> fd = detFDoFsLone(an.mesh, an.mpData), fdAll = activeCellDoFs(an.mesh);
      int lonelyFree = 0;
      for (int n : {n43, n44, n34})
        for (int i = 0; i < nD; ++i) lonelyFree += has(fd, dof(n, i));
      CHECK(lonelyFree == 2);                   // one node kept, x and y:
      CHECK(has(fd, dof(n34, 0)));              // the largest basis value, N = 0.8 x 0.3
      CHECK(has(fd, dof(n34, 1)));
      CHECK(fd.size() == fdAll.size() - 4);
      const SpMat Kt = detMPs(Eigen::VectorXd::Zero(an.mesh.nDoF()), an.mpData, Formulation::UL).Kt;
      CHECK(rankOf(Kt, fd) == int(fd.size()));            // non-singular
      CHECK(rankOf(Kt, fdAll) == int(fdAll.size()) - 4);  // the active-cell rule: singular
    }
  }
}

TEST_SUITE("detFDoFs") {
  TEST_CASE("detFDoFs: a GIMP point alone in a row of cells, across a grid line, keeps two of its three lone nodes per direction") {
    // a block of 2 x 2 GIMP points per cell (lp = 0.25) in cells [1,3) x [1,3), rollers
    // on y = 1; the point at (2.25, 2.75) moved to (2.1, 2.9): its domain [1.85, 2.35] x
    // [2.65, 3.15] pokes 0.15 into the empty row y in [3, 4] across x = 2, so the nodes
    // (1,4) (2,4) (3,4) are linked to it alone. There S_v = Sx_v Sy and dS_v =
    // (dSx_v Sy, Sx_v dSy): the point sees their u only through sum Sx_v u_v and
    // sum dSx_v u_v, one zero-energy mode per direction (Kt singular in exact
    // arithmetic: an LU finds a zero or a round-off pivot, by the summation order).
    // Sx = 0.0225, 0.855, 0.1225 ([AMPLE] eqs 25-26, regions A, C, E): node (1,4) goes.
    // The other top points' domains end exactly on y = 3 and x = 3: they link no
    // node of row y = 4 or column x = 4 (elemForMP: touching is not overlapping).
    Analysis an = testing::smallBlock(MpType::GIMP, CmType::Elastic, 2);
    size_t moved = an.mpData.size();
    for (size_t p = 0; p < an.mpData.size(); ++p)
      if ((an.mpData[p].mpC - Vector2d(2.25, 2.75)).norm() < 1e-12) moved = p;
    REQUIRE(moved < an.mpData.size());
    REQUIRE(an.mpData[moved].lp.isApprox(Vector2d(0.25, 0.25)));
    an.mpData[moved].mpC = Vector2d(2.1, 2.9);
    for (int n = 0; n < an.mesh.nodes(); ++n)
      if (std::abs(an.mesh.coord(n, 1) - 1.0) < 1e-12)
        for (int i = 0; i < nD; ++i) an.mesh.bc.push_back({dof(n, i), 0.0});
    elemMPinfo(an.mesh, an.mpData);
    const int n14 = 4 * 5 + 1, n24 = 4 * 5 + 2, n34 = 4 * 5 + 3, n44 = 4 * 5 + 4, n43 = 3 * 5 + 4;
    for (size_t p = 0; p < an.mpData.size(); ++p)
      for (int n : {n14, n24, n34}) CHECK(linked(an.mpData[p], n) == (p == moved));
    for (const MaterialPoint& mp : an.mpData) CHECK_FALSE((linked(mp, n44) || linked(mp, n43)));

    const std::vector<int> fd = detFDoFsLone(an.mesh, an.mpData), fdAll = activeCellDoFs(an.mesh);
    for (int i = 0; i < nD; ++i) {
      CHECK_FALSE(has(fd, dof(n14, i)));     // the smallest S of the three
      CHECK(has(fd, dof(n24, i)));
      CHECK(has(fd, dof(n34, i)));
    }
    CHECK(fd.size() == fdAll.size() - 2);
    // with stress (prestrain: E = 1e6, strains ~1e-3) the kept dofs' one rotation mode
    // (4 gradients, 3 strains) has its geometric stiffness; unstressed it would be zero
    std::vector<MaterialPoint> stressed = an.mpData;
    testing::prestrain(stressed, 7);
    const SpMat Kt = detMPs(Eigen::VectorXd::Zero(an.mesh.nDoF()), stressed, Formulation::UL).Kt;
    CHECK(rankOf(Kt, fd) == int(fd.size()));            // no pivot below 1e-10 of the largest
    CHECK(rankOf(Kt, fdAll) == int(fdAll.size()) - 2);  // all linked dofs: two null modes

    // the choice rests on per-point data, not on the summation order: moving every
    // point by a few ulps (as two threads' nodal sums move them) gives the same fd
    for (unsigned seed = 1; seed <= 5; ++seed) {
      std::vector<MaterialPoint> nudged = an.mpData;
      std::mt19937 gen(seed);
      std::uniform_real_distribution<double> r(-1.0, 1.0);
      for (MaterialPoint& mp : nudged) mp.mpC += 4e-16 * Vector2d(r(gen), r(gen)).cwiseProduct(mp.mpC);
      elemMPinfo(an.mesh, nudged);
      CHECK(detFDoFsLone(an.mesh, nudged) == fd);
    }
  }
}

TEST_SUITE("detFDoFs") {
  TEST_CASE("detFDoFs: the default collapse at the start of load step 34: a lone point's row, Kt(fd,fd) of full rank") {
    // [AMPLE] sec 5.3, a = 2, mp = 3 (h = 1 m, lp = 1/6 m): after step 33 the GIMP
    // point at (7.885, 6.938) pokes 0.10 h into the empty row y in [7, 8] across x = 8,
    // so three nodes of y = 8 are linked to it alone: the linked dofs carry two
    // zero-energy modes (pivots of round-off); detFDoFs leaves one dof per direction
    // out and keeps a system whose pivots are all real (above 1e-10 of the largest)
    const Setup* s = findSetup("collapse");
    REQUIRE(s != nullptr);
    Analysis an = s->setupGrid(s->params());
    RunLog log;
    solveRun(an, log, RunOptions{"", 0, true, 33});
    REQUIRE(log.lastConverged == 33);
    elemMPinfo(an.mesh, an.mpData);                    // step 34 as the analysis starts it
    const std::vector<int> fd = detFDoFsLone(an.mesh, an.mpData), fdAll = activeCellDoFs(an.mesh);
    CHECK(fd.size() == fdAll.size() - 2);
    const SpMat Kt = detMPsOf(Eigen::VectorXd::Zero(an.mesh.nDoF()), an.mpData, an.formulation).Kt;
    CHECK(rankOf(Kt, fd) == int(fd.size()));
    CHECK(rankOf(Kt, fdAll) == int(fdAll.size()) - 2);
  }

  TEST_CASE("detFDoFs: the collapse a = 4, mp = 4 on one and two threads: the same passes, positions and residual floors") {
    // 4,096 points: two threads' shares (pointShares). In load step 35 a point alone in
    // a row of cells links three lone nodes; were their redundant dofs solved for, the
    // LU would pivot on round-off and the two runs' last residuals of that step differ
    // 14-fold (3.0e-14 and 4.2e-13); with them left out every step's last residual is
    // at its round-off floor on both, within a factor 3, and the positions agree to 1e-10 m
#ifndef _OPENMP
    MESSAGE("built without AMPLE_OPENMP: one thread only, nothing to compare");
#else
    const int before = omp_get_max_threads();
    RunLog log[2];
    Analysis an[2];
    for (int run = 0; run < 2; ++run) {
      omp_set_num_threads(run + 1);
      an[run] = testing::runSetup("collapse", {{"a", 4}, {"mp", 4}}, log[run]);
    }
    omp_set_num_threads(before);
    REQUIRE(an[0].mpData.size() == 4096);
    CHECK(log[0].converged);
    CHECK(log[1].converged);
    REQUIRE(log[0].residuals.size() == log[1].residuals.size());
    std::map<int, std::array<double, 2>> last;       // per load step, its last residual
    for (size_t k = 0; k < log[0].residuals.size(); ++k) {
      const auto &r0 = log[0].residuals[k], &r1 = log[1].residuals[k];
      CHECK(r0.lstp == r1.lstp);
      CHECK(r0.NRit == r1.NRit);
      last[r0.lstp] = {r0.fErr, r1.fErr};
    }
    for (const auto& [lstp, f] : last) {
      CAPTURE(lstp);
      CHECK(std::max(f[0], f[1]) <= 3 * std::min(f[0], f[1]));
    }
    double dx = 0;
    for (size_t p = 0; p < an[0].mpData.size(); ++p)
      dx = std::max(dx, (an[0].mpData[p].mpC - an[1].mpData[p].mpC).cwiseAbs().maxCoeff());
    CHECK(dx <= 1e-10);
#endif
  }
}

TEST_SUITE("detFDoFs") {
  // points linked by hand, nodes listed in any order; lone = false: the free set of the
  // exercise alone ([AMPLE] sec 4), without the lone-node rules that follow it
  MaterialPoint linkedTo(MpType t, std::vector<int> nodes) {
    MaterialPoint mp;
    mp.mpType = t;
    mp.nn = int(nodes.size());  // nn and room for the nodes
    for (int v = 0; v < mp.nn; ++v) mp.nIN[v] = nodes[v];
    return mp;
  }
  TEST_CASE("detFDoFs: a 9-node GIMP point and an MPM point with its nodes out of order on one grid / one MPM point on another / in turn / bcs in x or y only") {
    // grid A: 3 x 3 cells, 4 nodes per row (node = 4 row + column), 32 dofs
    Mesh a = formCoord2D(3, 3, 3.0, 3.0);
    const std::vector<MaterialPoint> ptsA = {linkedTo(MpType::GIMP, {0, 1, 2, 4, 5, 6, 8, 9, 10}),
                                             linkedTo(MpType::MPM, {15, 11, 14, 10})};
    // node 0 held in x and y, node 5 in y only, node 15 in x only, node 3 (not linked) in y
    a.bc = {{dof(0, 0), 0.0}, {dof(0, 1), 0.0}, {dof(5, 1), 0.0}, {dof(15, 0), 0.02}, {dof(3, 1), 0.0}};
    std::vector<int> expectedA;
    for (int n : {1, 2, 4, 5, 6, 8, 9, 10, 11, 14, 15})
      for (int i = 0; i < nD; ++i)
        if (!(n == 5 && i == 1) && !(n == 15 && i == 0)) expectedA.push_back(dof(n, i));
    std::sort(expectedA.begin(), expectedA.end());
    // grid B: 2 x 1 cells, 6 nodes; one MPM point on cell 1 (nodes 1 2 4 5), node 2 held in x
    Mesh b = formCoord2D(2, 1, 2.0, 1.0);
    b.bc = {{dof(2, 0), 0.0}};
    const std::vector<MaterialPoint> ptsB = {linkedTo(MpType::MPM, {5, 4, 1, 2})};
    const std::vector<int> expectedB = {2, 3, 5, 8, 9, 10, 11};
    for (int round = 0; round < 2; ++round) {
      CAPTURE(round);
      CHECK(detFDoFs(a, ptsA) == expectedA);
      CHECK(detFDoFs(b, ptsB) == expectedB);
    }
    // without the bcs: every dof of the linked nodes, and only those
    a.bc.clear();
    std::vector<int> all;
    for (int n : {0, 1, 2, 4, 5, 6, 8, 9, 10, 11, 14, 15})
      for (int i = 0; i < nD; ++i) all.push_back(dof(n, i));
    CHECK(detFDoFs(a, ptsA) == all);
  }
  TEST_CASE("detFDoFs: a node reached by one point is as free as one reached by many / the order of the points does not matter") {
    Mesh m = formCoord2D(3, 1, 3.0, 1.0);                 // 8 nodes: 0-3 bottom, 4-7 top
    std::vector<MaterialPoint> pts = {linkedTo(MpType::MPM, {0, 1, 4, 5}), linkedTo(MpType::MPM, {1, 2, 5, 6}),
                                      linkedTo(MpType::MPM, {1, 2, 5, 6}), linkedTo(MpType::MPM, {2, 3, 6, 7})};
    std::vector<int> all(16);
    for (int d = 0; d < 16; ++d) all[d] = d;
    CHECK(detFDoFs(m, pts) == all);
    std::reverse(pts.begin(), pts.end());
    CHECK(detFDoFs(m, pts) == all);
    pts.resize(1);                                        // only the point of cell 2: nodes 2 3 6 7
    CHECK(detFDoFs(m, pts) == std::vector<int>{4, 5, 6, 7, 12, 13, 14, 15});
  }
}
