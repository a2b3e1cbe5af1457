// Tests of detMPs (the material point loop): the assembled tangent against
// central finite differences of the assembled internal force, and a
// homogeneous-deformation patch test.
#include "ample/detMPs.h"
#include "ample/fast/detMPsFast.h"
#include "ample/solver/pointShares.h"
#include "ample/solver/stiffnessPattern.h"
#include "constitutive/Hooke3d.h"
#include "ample/stiffness/tensorOps.h"
#include "testProblems.h"
#include <doctest/doctest.h>
#include <cmath>
#include <random>
#ifdef _OPENMP
#include <omp.h>
#endif

using namespace ample;


TEST_SUITE("detMPs") {
  TEST_CASE("detMPs: tangent equals central differences of fint (elastic / plastic / MPM / GIMP / UL and PC)") {
    for (MpType t : {MpType::MPM, MpType::GIMP})
      for (CmType c : {CmType::Elastic, CmType::VonMises}) {
        CAPTURE(int(t));
        CAPTURE(int(c));
        Analysis an = testing::smallBlock(t, c);
        testing::prestrain(an.mpData, 7);
        for (MaterialPoint& mp : an.mpData) mp.mpC += Vector2d(0.13, -0.07);  // GIMP domains straddle edges
        elemMPinfo(an.mesh, an.mpData);
        const Eigen::VectorXd uvw = testing::randomUvw(an, 0.02, 11);
        if (c == CmType::VonMises) {  // every point must be yielding for a smooth FD
          detMPs(uvw, an.mpData);
          for (const MaterialPoint& mp : an.mpData) {  // Kirchhoff stress on the surface
            const Vector6d tau = mp.sig * mp.F.determinant();
            const double p = tau.head<3>().sum() / 3.0;
            const double rho = std::sqrt((tau.head<3>().array() - p).square().sum() +
                                         2.0 * tau.tail<3>().squaredNorm());
            REQUIRE(rho == doctest::Approx(mp.mCst.rhoY).epsilon(1e-10));
          }
        }
        CHECK(testing::tangentError(an, uvw, Formulation::UL) < 1e-6);
        // PC ([Lagrangian] sec 5): the stress paired with dS/dX~ is P~, not symmetric, so
        // eq 16 must contract its second index with the gradient
        CHECK(testing::tangentError(an, uvw, Formulation::PC) < 1e-6);
      }
  }

  TEST_CASE("detMPs: with no increment a point keeps the stress of its converged elastic strain (Hencky, by hand: exp(2 eps_e,n) then ln / 2)") {
    // du = 0: dF = I, F = Fn, b_e,tr = exp(2 eps_e,n) (eq 9), eps_e,tr = ln(b_e,tr) / 2 = eps_e,n
    // (eq 10), tau = lambda tr(eps) I + 2 mu eps, sigma = tau / det(Fn) (eqs 5-6); UL and PC
    for (Formulation form : {Formulation::UL, Formulation::PC}) {
      Analysis an = testing::smallBlock(MpType::GIMP, CmType::Elastic);
      testing::prestrain(an.mpData, 4);
      elemMPinfo(an.mesh, an.mpData);
      DetMPsOut out;
      pointLoopOf(form)(Eigen::VectorXd::Zero(an.mesh.nDoF()), an.mpData, form, out);  // UL: detMPs
      const double E = 1e6, nu = 0.3, lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
      double worst = 0.0;
      for (const MaterialPoint& mp : an.mpData) {
        const Vector6d& e = mp.epsEn;                 // engineering shears e(3..5)
        Vector6d tau;
        tau << lam * (e(0) + e(1) + e(2)) + 2 * mu * e(0), lam * (e(0) + e(1) + e(2)) + 2 * mu * e(1),
            lam * (e(0) + e(1) + e(2)) + 2 * mu * e(2), mu * e(3), mu * e(4), mu * e(5);
        worst = std::max(worst, (mp.sig - tau / mp.Fn.determinant()).norm() / tau.norm());
      }
      CAPTURE(int(form));
      CHECK(worst <= 1e-10);                          // exp then log: round-off of 1e-3 strains
    }
  }

  TEST_CASE("detMPs: zero increment on an unstressed body gives zero internal force, a small one K du") {
    Analysis an = testing::smallBlock(MpType::GIMP, CmType::Elastic);
    elemMPinfo(an.mesh, an.mpData);
    const DetMPsOut out = detMPs(Eigen::VectorXd::Zero(an.mesh.nDoF()), an.mpData);
    CHECK(out.fint.norm() == 0.0);
    // a small increment (strains ~1e-6) gives the linear response fint = Kt(0) du to
    // second order, and that response is not zero
    const Eigen::VectorXd du = testing::randomUvw(an, 1e-6, 5);
    const Eigen::VectorXd f = detMPs(du, an.mpData).fint, Kdu = out.Kt * du;
    CHECK(f.norm() > 0.0);
    CHECK((f - Kdu).norm() <= 1e-4 * f.norm());
  }

  TEST_CASE("detMPs: homogeneous deformation gives uniform stress, no interior force, and the nodal forces' moment det(F) V0 sigma") {
    for (MpType t : {MpType::MPM, MpType::GIMP}) {
      Analysis an = testing::smallBlock(t, CmType::Elastic, 3);
      elemMPinfo(an.mesh, an.mpData);
      Eigen::Matrix2d H;
      H << 0.10, 0.04, -0.03, -0.05;  // displacement gradient of the patch
      Eigen::VectorXd uvw(an.mesh.nDoF());
      for (int n = 0; n < an.mesh.nodes(); ++n)
        uvw.segment<2>(2 * n) = H * an.mesh.coord.row(n).transpose();
      const DetMPsOut out = detMPs(uvw, an.mpData);

      Matrix3d F = Matrix3d::Identity();  // analytic Hencky stress of F = I + H
      F.topLeftCorner<2, 2>() += H;
      const Vector6d eps = tensorToStrain(0.5 * symLog(F * F.transpose()));
      const Vector6d sigA = Hooke3d(eps, an.mpData[0].mCst).Ksig / F.determinant();
      for (const MaterialPoint& mp : an.mpData)
        CHECK((mp.sig - sigA).norm() <= 1e-10 * sigA.norm());
      const int centre = 2 * 5 + 2;  // node (2, 2): interior to the block
      CHECK(out.fint.segment<2>(2 * centre).norm() <= 1e-10 * sigA.norm());
      // the first moment of the nodal forces about the moved nodes is the stress times the
      // current volume: sum_a x_a (x) f_a = sum_p V_p sigma = det(F) V0 sigma (eq 16 with
      // sum_a x_a (x) dS_a/dx = I, V_p = det(F) V_p0 in a homogeneous deformation)
      Eigen::Matrix2d M = Eigen::Matrix2d::Zero();
      for (int n = 0; n < an.mesh.nodes(); ++n)
        M += (an.mesh.coord.row(n).transpose() + uvw.segment<2>(2 * n)) * out.fint.segment<2>(2 * n).transpose();
      double V0 = 0.0;
      for (const MaterialPoint& mp : an.mpData) V0 += mp.vp0;
      const Eigen::Matrix2d sig2 = stressToTensor(sigA).topLeftCorner<2, 2>();
      CHECK((M - F.determinant() * V0 * sig2).norm() <= 1e-10 * V0 * sig2.norm());
    }
  }
}

TEST_SUITE("detMPs") {
  // GIMP points, mp x mp in each of cells x cells (a margin of 2 cells), plastic,
  // prestrained: 4,096 points for cells = 16, mp = 4, two threads' shares
  Analysis largeBlock(int cells = 16, int mp = 4) {
    Common p;
    p.mp = mp;
    p.mpType = MpType::GIMP;
    p.cmType = CmType::VonMises;
    p.E = 1e6;
    p.nu = 0.3;
    p.rhoY = 2e3;
    Analysis an;
    an.mesh = formCoord2D(cells + 4, cells + 4, cells + 4.0, cells + 4.0);
    fillBlock(an.mpData, Vector2d(2, 2), cells, cells, an.mesh.h, p, 1000.0);
    testing::prestrain(an.mpData, 3);
    elemMPinfo(an.mesh, an.mpData);
    return an;
  }

  TEST_CASE("detMPsFast: on 2, 3 and 4 threads it gives its own one-thread fint, Kt and point states bit for bit (UL, PC, SS)") {
#ifndef _OPENMP
    MESSAGE("built without AMPLE_OPENMP: the point loop is serial, nothing to compare");
#else
    // 16,384 points in 32 x 32 cells; and 9,216 crowded into 4 x 4 cells (24 x 24 each), where
    // a thread owns a few nodes and most points link two threads' nodes. (Against the plain
    // loops, within round-off: tests/test_pointLoops.cpp.)
    for (const Analysis& an : {largeBlock(32), largeBlock(4, 24)}) {
      const int np = int(an.mpData.size());
      CAPTURE(np);
      REQUIRE(np >= 4 * pointsPerThread());
      const Eigen::VectorXd uvw = testing::randomUvw(an, 0.05, 5);
      const int before = omp_get_max_threads();
      for (Formulation form : {Formulation::UL, Formulation::PC, Formulation::SS}) {
        CAPTURE(int(form));
        std::vector<DetMPsOut> out(5);                     // nt: detMPsFast on nt threads
        std::vector<std::vector<MaterialPoint>> mps(5, an.mpData);
        for (double pass : {1.0, 0.5}) {                   // a second pass: what the step's plan kept
          CAPTURE(pass);
          for (int nt = 1; nt <= 4; ++nt) {
            omp_set_num_threads(nt);
            REQUIRE(pointThreads(int(an.mpData.size())) == std::min(nt, np / pointsPerThread()));
            detMPsFast(pass * uvw, mps[nt], form, out[nt]);
          }
          omp_set_num_threads(before);
          CHECK(out[1].plan->blocked);                       // the fast assembly did run
          CHECK(out[1].Kt.norm() > 0);
          for (int nt = 2; nt <= 4; ++nt) {
            CAPTURE(nt);
            CHECK((out[nt].fint.array() == out[1].fint.array()).all());
            CHECK((out[nt].Kt.coeffs() == out[1].Kt.coeffs()).all());
            bool same = true;
            for (size_t p = 0; p < mps[1].size(); ++p)
              same = same && mps[nt][p].sig == mps[1][p].sig && mps[nt][p].F == mps[1][p].F &&
                     mps[nt][p].epsE == mps[1][p].epsE;
            CHECK(same);
          }
        }
      }
    }
#endif
  }

  TEST_CASE("detMPsFast: a pattern grown beyond node blocks (ghost penalty, IB terms) is assembled by the general walk, to the same values") {
    Analysis an = largeBlock();
    const Eigen::VectorXd uvw = testing::randomUvw(an, 0.05, 6);
    DetMPsOut plain, grown;
    std::vector<MaterialPoint> a = an.mpData, b = an.mpData;
    detMPsFast(uvw, a, Formulation::UL, plain);
    CHECK(plain.plan->blocked);
    const int n = an.mesh.nDoF();
    SpMat extra(n, n);                                // one x-x coupling of two far nodes only
    extra.insert(0, n - 2) = 0.0;
    extra.insert(n - 2, 0) = 0.0;
    grown.Kt = stiffnessPattern(n, an.mpData) + extra;
    detMPsFast(uvw, b, Formulation::UL, grown);
    CHECK_FALSE(grown.plan->blocked);
    CHECK((Eigen::MatrixXd(grown.Kt) - Eigen::MatrixXd(plain.Kt)).norm() == 0.0);
    CHECK((grown.fint - plain.fint).norm() == 0.0);
  }
}

TEST_SUITE("stiffnessPattern") {
  TEST_CASE("addNodeBlocks: at the blocks nodeBlockPositions found it adds a point stiffness exactly as addToPattern does") {
    Analysis an = testing::smallBlock(MpType::GIMP, CmType::Elastic, 3);
    for (MaterialPoint& mp : an.mpData) mp.mpC += Vector2d(0.13, -0.07);
    elemMPinfo(an.mesh, an.mpData);
    const SpMat K = stiffnessPattern(an.mesh.nDoF(), an.mpData);
    CHECK(nodeBlocked(K));
    std::mt19937 gen(2);
    std::uniform_real_distribution<double> r(-1.0, 1.0);
    std::vector<double> v1(K.nonZeros(), 0.0), v2(K.nonZeros(), 0.0);
    for (const MaterialPoint& mp : an.mpData) {
      const int ne = nD * mp.nn;
      Eigen::MatrixXd ke(ne, ne);
      for (int c = 0; c < ne; ++c)
        for (int q = 0; q < ne; ++q) ke(q, c) = r(gen);
      int d[nD * MAXN];
      for (int a = 0; a < mp.nn; ++a)
        for (int i = 0; i < nD; ++i) d[nD * a + i] = dof(mp.nIN[a], i);
      addToPattern(K, v1.data(), d, ne, ke);
      int at[MAXN * MAXN];
      nodeBlockPositions(K, mp.nIN.data(), mp.nn, at);
      addNodeBlocks(K, v2.data(), mp.nIN.data(), mp.nn, at, ke);
    }
    CHECK(v1 == v2);
    double sum = 0.0;
    for (double x : v1) sum += std::abs(x);
    CHECK(sum > 0.0);
    SpMat lone = K;                                   // a lone x-x entry breaks the blocks
    SpMat extra(K.rows(), K.cols());
    extra.insert(0, K.cols() - 2) = 0.0;
    lone = lone + extra;
    CHECK_FALSE(nodeBlocked(lone));
  }


  TEST_CASE("stiffnessPattern: nodes that share a point are coupled and no others") {
    Analysis an = testing::smallBlock(MpType::MPM, CmType::Elastic, 2);  // 2 x 2 cells, 9 nodes
    elemMPinfo(an.mesh, an.mpData);
    const SpMat K = stiffnessPattern(an.mesh.nDoF(), an.mpData);
    CHECK(K.nonZeros() == 4 * (4 * 4 + 4 * 6 + 9));  // corner, edge, centre nodes: 2x2 dof blocks
    CHECK(K.isCompressed());
    CHECK(Eigen::MatrixXd(K).cwiseAbs().sum() == 0.0);
    Eigen::MatrixXd structure = Eigen::MatrixXd::Zero(K.rows(), K.cols());
    for (int c = 0; c < K.outerSize(); ++c)
      for (SpMat::InnerIterator it(K, c); it; ++it) structure(it.row(), c) = 1.0;
    CHECK((structure - structure.transpose()).norm() == 0.0);  // symmetric pattern
  }
}

// Points made by hand on a 2 x 2 grid of 1 m cells (node n = 3 row + column at (column,
// row)): their nodes, basis values and gradients written out (eqs 22-26), so that only
// detMPs and the constitutive law run (no elemMPinfo). Small strain (SS) needs Hooke3d
// alone; the eqs 14 and 16 sums are written out here against the law sigma = lambda tr(eps)
// 1 + 2 mu eps, A_ijkl = lambda d_ij d_kl + mu (d_ik d_jl + d_il d_jk).
TEST_SUITE("detMPs") {
  struct Basis1 {
    std::vector<int> at;             // node coordinate (0, 1, 2)
    std::vector<double> S, dS;
  };
  // 1D values of a GIMP point (l = 0.25, h = 1) at 1.1 and 0.9, of MPM points at 0.3, 0.6, 1.7, 1.4
  Basis1 gimp11() { return {{0, 1, 2}, {0.0225, 0.855, 0.1225}, {-0.3, -0.4, 0.7}}; }
  Basis1 gimp09() { return {{0, 1, 2}, {0.1225, 0.855, 0.0225}, {-0.7, 0.4, 0.3}}; }
  Basis1 mpm(double x) {             // the hat functions of the cell holding x
    const int c = int(x);
    const double r = x - c;
    return {{c, c + 1}, {1 - r, r}, {-1.0, 1.0}};
  }
  // a point of the tensor-product basis bx (x) by, material m, volume V
  MaterialPoint handPoint(const Basis1& bx, const Basis1& by, MpType type, const MaterialConstants& m, double V) {
    MaterialPoint mp;
    mp.mpType = type;
    mp.cmType = CmType::Elastic;
    mp.mCst = m;
    mp.vp = mp.vp0 = V;
    mp.nn = int(bx.at.size() * by.at.size());  // nn and room for the basis
    for (size_t b = 0; b < by.at.size(); ++b)
      for (size_t a = 0; a < bx.at.size(); ++a) {
        const int v = int(b * bx.at.size() + a);
        mp.nIN[v] = 3 * by.at[b] + bx.at[a];
        mp.Svp[v] = bx.S[a] * by.S[b];
        mp.dSvp(0, v) = bx.dS[a] * by.S[b];
        mp.dSvp(1, v) = bx.S[a] * by.dS[b];
      }
    return mp;
  }
  const MaterialConstants matA{1e6, 0.3, 2e3}, matB{3e5, 0.15, 1e3};
  std::vector<MaterialPoint> handPoints() {
    std::vector<MaterialPoint> pts = {handPoint(gimp11(), gimp09(), MpType::GIMP, matA, 0.25),
                                      handPoint(mpm(0.3), mpm(0.6), MpType::MPM, matB, 0.2),
                                      handPoint(mpm(1.7), mpm(1.4), MpType::MPM, matA, 0.3),
                                      handPoint(mpm(1.2), mpm(0.3), MpType::MPM, matB, 0.15)};
    pts[0].epsEn << 1e-3, -5e-4, 2e-4, 6e-4, 0, 0;   // earlier (small) strains
    pts[1].epsEn << -4e-4, 8e-4, 0, -3e-4, 0, 0;
    pts[3].epsEn << 2e-4, 3e-4, -1e-4, 9e-4, 0, 0;
    return pts;
  }
  Eigen::VectorXd handUvw(double size) {  // 9 nodes, 18 dofs
    Eigen::VectorXd u(18);
    for (int d = 0; d < 18; ++d) u(d) = size * std::sin(1.7 * d + 0.3);
    return u;
  }
  double lamOf(const MaterialConstants& m) { return m.E * m.nu / ((1 + m.nu) * (1 - 2 * m.nu)); }
  double muOf(const MaterialConstants& m) { return m.E / (2 * (1 + m.nu)); }
  // eqs 16 and 14 by hand for SS: f = sum_p sum_j dS_ja sigma_ij V, K = sum_p dS_ja A_ijkl dS_lb V
  void handSS(const std::vector<MaterialPoint>& pts, const Eigen::VectorXd& u, Eigen::VectorXd& f,
              Eigen::MatrixXd& K) {
    f = Eigen::VectorXd::Zero(18);
    K = Eigen::MatrixXd::Zero(18, 18);
    for (const MaterialPoint& mp : pts) {
      Eigen::Matrix2d H = Eigen::Matrix2d::Zero();   // grad du
      for (int v = 0; v < mp.nn; ++v)
        for (int i = 0; i < 2; ++i)
          for (int j = 0; j < 2; ++j) H(i, j) += u(2 * mp.nIN[v] + i) * mp.dSvp(j, v);
      Matrix3d e;                                     // eps_n + sym(H), tensor shears
      const Vector6d& n = mp.epsEn;
      e << n(0), n(3) / 2, n(5) / 2, n(3) / 2, n(1), n(4) / 2, n(5) / 2, n(4) / 2, n(2);
      e.topLeftCorner<2, 2>() += 0.5 * (H + H.transpose());
      const double l = lamOf(mp.mCst), mu = muOf(mp.mCst);
      const Matrix3d s = l * e.trace() * Matrix3d::Identity() + 2 * mu * e;
      auto A = [&](int i, int j, int k, int q) {
        return l * (i == j) * (k == q) + mu * ((i == k) * (j == q) + (i == q) * (j == k));
      };
      for (int a = 0; a < mp.nn; ++a)
        for (int i = 0; i < 2; ++i) {
          for (int j = 0; j < 2; ++j) f(2 * mp.nIN[a] + i) += mp.dSvp(j, a) * s(i, j) * mp.vp;
          for (int b = 0; b < mp.nn; ++b)
            for (int k = 0; k < 2; ++k)
              for (int j = 0; j < 2; ++j)
                for (int q = 0; q < 2; ++q)
                  K(2 * mp.nIN[a] + i, 2 * mp.nIN[b] + k) += mp.dSvp(j, a) * A(i, j, k, q) * mp.dSvp(q, b) * mp.vp;
        }
    }
  }

  TEST_CASE("detMPs: small strain on points made by hand (a 9-node GIMP point and MPM points sharing its nodes of two materials): fint and Kt of eqs 16 and 14") {
    const std::vector<MaterialPoint> start = handPoints();
    for (double size : {0.0, 1e-3, 4e-3}) {           // two increments and none, in turn
      CAPTURE(size);
      std::vector<MaterialPoint> pts = start;
      const Eigen::VectorXd u = handUvw(size);
      const DetMPsOut out = detMPsOf(u, pts, Formulation::SS);
      Eigen::VectorXd f;
      Eigen::MatrixXd K;
      handSS(start, u, f, K);
      CHECK((out.fint - f).norm() <= 1e-12 * f.norm());
      CHECK((Eigen::MatrixXd(out.Kt) - K).norm() <= 1e-12 * K.norm());
      // each point alone: the sum over the points is the assembly, nothing more
      Eigen::VectorXd sum = Eigen::VectorXd::Zero(18);
      for (const MaterialPoint& mp : start) {
        std::vector<MaterialPoint> one = {mp};
        sum += detMPsOf(u, one, Formulation::SS).fint;
      }
      CHECK((sum - f).norm() <= 1e-12 * f.norm());
    }
  }
  TEST_CASE("detMPs: small strain with a homogeneous gradient on hand points: no net force / the first moment sum_a X_a (x) f_a = sum_p V_p sigma_p") {
    std::vector<MaterialPoint> pts = handPoints();
    for (MaterialPoint& mp : pts) mp.epsEn.setZero();
    Eigen::Matrix2d G;
    G << 2e-3, -1e-3, 5e-4, -1.5e-3;
    Eigen::VectorXd u(18);
    for (int n = 0; n < 9; ++n) u.segment<2>(2 * n) = G * Vector2d(n % 3, n / 3);
    const DetMPsOut out = detMPsOf(u, pts, Formulation::SS);
    Eigen::Matrix2d M = Eigen::Matrix2d::Zero(), expected = Eigen::Matrix2d::Zero();
    Vector2d net = Vector2d::Zero();
    for (int n = 0; n < 9; ++n) {
      net += out.fint.segment<2>(2 * n);
      M += Vector2d(n % 3, n / 3) * out.fint.segment<2>(2 * n).transpose();
    }
    const Eigen::Matrix2d e = 0.5 * (G + G.transpose());
    for (const MaterialPoint& mp : pts) {               // sigma = lambda tr(e) 1 + 2 mu e, in plane
      const Eigen::Matrix2d s = lamOf(mp.mCst) * e.trace() * Eigen::Matrix2d::Identity() + 2 * muOf(mp.mCst) * e;
      expected += mp.vp * s;
      CHECK((stressToTensor(mp.sig).topLeftCorner<2, 2>() - s).norm() <= 1e-12 * s.norm());
    }
    CHECK(net.norm() <= 1e-12 * expected.norm());
    CHECK((M - expected).norm() <= 1e-12 * expected.norm());
  }
  // finite strain on the same hand points: the tangent against central differences of fint
  double handTangentError(Formulation form) {
    std::vector<MaterialPoint> pts = handPoints();
    for (size_t p = 0; p < pts.size(); ++p) {        // a converged state with stress
      pts[p].Fn << 1.02 + 0.01 * p, 0.03, 0, -0.02, 0.97, 0, 0, 0, 1;
      pts[p].vp = pts[p].Fn.determinant() * pts[p].vp0;
    }
    const Eigen::VectorXd u = handUvw(5e-3);
    std::vector<MaterialPoint> work = pts;
    const Eigen::MatrixXd Kt = Eigen::MatrixXd(detMPsOf(u, work, form).Kt);
    Eigen::MatrixXd Kfd(18, 18);
    const double d = 1e-7;
    for (int c = 0; c < 18; ++c) {
      Eigen::VectorXd up = u, um = u;
      up(c) += d;
      um(c) -= d;
      std::vector<MaterialPoint> a = pts, b = pts;
      Kfd.col(c) = (detMPsOf(up, a, form).fint - detMPsOf(um, b, form).fint) / (2 * d);
    }
    return (Kt - Kfd).norm() / Kt.norm();
  }
  TEST_CASE("detMPs: PC on hand points with a converged state: the tangent equals central differences of fint") {
    CHECK(handTangentError(Formulation::PC) < 1e-6);
  }
  TEST_CASE("detMPs: UL on hand points with a converged state: the tangent equals central differences of fint") {
    CHECK(handTangentError(Formulation::UL) < 1e-6);
  }
}
