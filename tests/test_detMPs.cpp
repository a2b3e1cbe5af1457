// Tests of detMPs (the material point loop): the assembled tangent against
// central finite differences of the assembled internal force, and a
// homogeneous-deformation patch test.
#include "ample/detMPs.h"
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
            REQUIRE(rho == doctest::Approx(mp.mCst(2)).epsilon(1e-10));
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
      detMPs(Eigen::VectorXd::Zero(an.mesh.nDoF()), an.mpData, form, out);
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
  // 4,096 GIMP points (16 x 16 cells, 4 x 4 each), plastic, prestrained: two threads' shares
  Analysis largeBlock() {
    Params P = commonParams(1);
    for (auto kv : std::vector<std::pair<const char*, double>>{
             {"mp", 4}, {"mpType", 2}, {"cmType", 2}, {"E", 1e6}, {"nu", 0.3}, {"rhoY", 2e3}})
      setDefault(P, kv.first, kv.second);
    Analysis an;
    an.mesh = formCoord2D(20, 20, 20.0, 20.0);
    fillBlock(an.mpData, Vector2d(2, 2), 16, 16, an.mesh.h, P, 1000.0);
    testing::prestrain(an.mpData, 3);
    elemMPinfo(an.mesh, an.mpData);
    return an;
  }

  TEST_CASE("detMPs: the point loop on two threads equals the serial loop to 1e-12 and repeats bit for bit") {
#ifndef _OPENMP
    MESSAGE("built without AMPLE_OPENMP: the point loop is serial, nothing to compare");
#else
    Analysis an = largeBlock();
    REQUIRE(an.mpData.size() == 4096);
    const Eigen::VectorXd uvw = testing::randomUvw(an, 0.05, 5);
    const int before = omp_get_max_threads();
    std::vector<DetMPsOut> out(3);
    for (int run = 0; run < 3; ++run) {               // serial, then two threaded runs
      omp_set_num_threads(run == 0 ? 1 : 2);
      std::vector<MaterialPoint> mps = an.mpData;
      detMPs(uvw, mps, Formulation::UL, out[run]);
    }
    omp_set_num_threads(before);
    const double dK = (out[1].Kt - out[0].Kt).norm() / out[0].Kt.norm();
    const double df = (out[1].fint - out[0].fint).norm() / out[0].fint.norm();
    CHECK(dK <= 1e-12);
    CHECK(df <= 1e-12);
    CHECK(out[1].part.size() == 1);                   // it did run on two threads
    CHECK((out[2].Kt - out[1].Kt).norm() == 0.0);     // deterministic for a thread count
    CHECK((out[2].fint - out[1].fint).norm() == 0.0);
#endif
  }

  TEST_CASE("detMPs: a pattern grown beyond node blocks (ghost penalty, IB terms) is assembled by the general walk, to the same values") {
    Analysis an = largeBlock();
    const Eigen::VectorXd uvw = testing::randomUvw(an, 0.05, 6);
    DetMPsOut plain, grown;
    std::vector<MaterialPoint> a = an.mpData, b = an.mpData;
    detMPs(uvw, a, Formulation::UL, plain);
    CHECK(plain.blocked);
    const int n = an.mesh.nDoF();
    SpMat extra(n, n);                                // one x-x coupling of two far nodes only
    extra.insert(0, n - 2) = 0.0;
    extra.insert(n - 2, 0) = 0.0;
    grown.Kt = stiffnessPattern(n, an.mpData) + extra;
    detMPs(uvw, b, Formulation::UL, grown);
    CHECK_FALSE(grown.blocked);
    CHECK((Eigen::MatrixXd(grown.Kt) - Eigen::MatrixXd(plain.Kt)).norm() == 0.0);
    CHECK((grown.fint - plain.fint).norm() == 0.0);
  }
}

TEST_SUITE("stiffnessPattern") {
  TEST_CASE("addNodeBlocks: the node-pair walk adds a point stiffness exactly as addToPattern does") {
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
      addNodeBlocks(K, v2.data(), mp.nIN.data(), mp.nn, ke);
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
