// Tests of detFDoFs and detExtForce on a small block of points.
#include "ample/detExtForce.h"
#include "ample/detFDoFs.h"
#include "testProblems.h"
#include <doctest/doctest.h>

using namespace ample;

TEST_SUITE("detFDoFs") {
  TEST_CASE("detFDoFs: dofs of the nodes of active cells less the constrained ones") {
    Analysis an = testing::smallBlock(MpType::MPM, CmType::Elastic, 2);  // cells 5, 6, 9, 10
    an.mesh.bc = {{dof(6, 0), 0.0}, {dof(0, 1), 0.0}};
    elemMPinfo(an.mesh, an.mpData);
    const std::vector<int> fd = detFDoFs(an.mesh);
    CHECK(fd.size() == 9 * 2 - 1);  // 9 nodes of the 2 x 2 active cells, one dof fixed
    for (size_t k = 1; k < fd.size(); ++k) CHECK(fd[k] > fd[k - 1]);
    CHECK(std::find(fd.begin(), fd.end(), dof(6, 0)) == fd.end());
    CHECK(std::find(fd.begin(), fd.end(), dof(6, 1)) != fd.end());
    CHECK(std::find(fd.begin(), fd.end(), dof(0, 0)) == fd.end());  // node 0: no point near
  }
}

TEST_SUITE("detExtForce") {
  TEST_CASE("detExtForce: nodal forces sum to the weight plus the point forces") {
    for (MpType t : {MpType::MPM, MpType::GIMP}) {
      Analysis an = testing::smallBlock(t, CmType::Elastic, 3);
      an.mpData[4].fp = Vector2d(300.0, -50.0);
      elemMPinfo(an.mesh, an.mpData);
      const Eigen::VectorXd f = detExtForce(an.mesh.nDoF(), 9.81, an.mpData);
      double fx = 0, fy = 0, m = 0;
      for (int n = 0; n < an.mesh.nodes(); ++n) {
        fx += f(dof(n, 0));
        fy += f(dof(n, 1));
      }
      for (const MaterialPoint& mp : an.mpData) m += mp.mpM;
      CHECK(m == doctest::Approx(1000.0 * 4.0).epsilon(1e-13));  // rho x block area
      CHECK(fx == doctest::Approx(300.0).epsilon(1e-12));
      CHECK(fy == doctest::Approx(-9.81 * m - 50.0).epsilon(1e-12));
      const MaterialPoint& p = an.mpData[4];  // the point force is spread by S_vp
      for (int v = 0; v < p.nn; ++v) CHECK(p.Svp[v] >= 0.0);
    }
  }
}
