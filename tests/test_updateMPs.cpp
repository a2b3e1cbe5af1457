// Tests of updateMPs (seed 002 eqs 15, 33, 34) and the stretch tensor.
#include "ample/detMPs.h"
#include "ample/updateMPs.h"
#include "testProblems.h"
#include <doctest/doctest.h>

using namespace ample;

TEST_SUITE("updateMPs") {
  TEST_CASE("updateMPs: stretchTensor gives U symmetric with U U = F'F and R orthogonal") {
    Matrix3d F;
    F << 1.2, 0.4, 0, -0.3, 0.9, 0, 0, 0, 1.1;
    const Matrix3d U = stretchTensor(F), R = F * U.inverse();
    CHECK((U - U.transpose()).norm() <= 1e-14);
    CHECK((U * U - F.transpose() * F).norm() <= 1e-13);
    CHECK((R.transpose() * R - Matrix3d::Identity()).norm() <= 1e-13);
  }
  TEST_CASE("updateMPs: positions, volumes and GIMP domains after a homogeneous step") {
    for (MpType t : {MpType::MPM, MpType::GIMP}) {
      Analysis an = testing::smallBlock(t, CmType::Elastic, 2);
      elemMPinfo(an.mesh, an.mpData);
      Eigen::Matrix2d H;
      H << 0.1, 0.0, 0.0, -0.2;  // stretch x, compress y
      const Vector2d shift(0.05, -0.02);
      Eigen::VectorXd uvw(an.mesh.nDoF());
      for (int n = 0; n < an.mesh.nodes(); ++n)
        uvw.segment<2>(2 * n) = shift + H * an.mesh.coord.row(n).transpose();
      detMPs(uvw, an.mpData);  // sets F of every point
      std::vector<MaterialPoint> before = an.mpData;
      updateMPs(uvw, an.mpData);
      for (size_t p = 0; p < before.size(); ++p) {
        const MaterialPoint &a = before[p], &b = an.mpData[p];
        CHECK((b.mpC - (a.mpC + shift + H * a.mpC)).norm() <= 1e-13);
        CHECK(b.vp == doctest::Approx(1.1 * 0.8 * a.vp0).epsilon(1e-13));
        const Vector2d lpExpected = a.lp0.cwiseProduct(Vector2d(1.1, 0.8));
        CHECK((b.lp - lpExpected).norm() <= 1e-14);  // MPM: lp0 = 0 stays 0
        CHECK(b.Fn == b.F);
        CHECK(b.epsEn == b.epsE);
      }
    }
  }
}
