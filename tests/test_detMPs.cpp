// Tests of detMPs (the material point loop): the assembled tangent against
// central finite differences of the assembled internal force, and a
// homogeneous-deformation patch test.
#include "ample/detMPs.h"
#include "ample/stiffnessPattern.h"
#include "constitutive/Hooke3d.h"
#include "ample/tensorOps.h"
#include "testProblems.h"
#include <doctest/doctest.h>
#include <cmath>

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
        // PC (seed 000 sec 5): the stress paired with dS/dX~ is P~, not symmetric, so
        // eq 16 must contract its second index with the gradient
        CHECK(testing::tangentError(an, uvw, Formulation::PC) < 1e-6);
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

TEST_SUITE("stiffnessPattern") {
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
