// Tests of detFDoFs (seed 002 sec 4, sec 5.3): the free degrees of freedom are
// those of the nodes of active cells, less the constrained ones, ascending.
#include "ample/detFDoFs.h"
#include "ample/formCoord2D.h"
#include <doctest/doctest.h>
#include <algorithm>

using namespace ample;

TEST_SUITE("detFDoFs") {
  TEST_CASE("detFDoFs: all dofs of a fully active grid without constraints") {
    Mesh mesh = formCoord2D(2, 1, 2.0, 1.0);  // 6 nodes, 12 dofs
    mesh.eInA.assign(mesh.nels(), 1);
    std::vector<int> all(12);
    for (int d = 0; d < 12; ++d) all[d] = d;
    CHECK(detFDoFs(mesh) == all);
  }
  TEST_CASE("detFDoFs: only nodes of active cells / minus the bc dofs / ascending") {
    Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);  // 5 nodes per row
    mesh.eInA.assign(mesh.nels(), 0);
    mesh.eInA[5] = mesh.eInA[6] = 1;           // nodes 6 7 8 11 12 13
    mesh.bc = {{dof(7, 0), 0.0}, {dof(12, 1), 0.1}, {dof(0, 1), 0.0}};  // node 0 is inactive
    const std::vector<int> expected = {dof(6, 0),  dof(6, 1),  /* 7x held */ dof(7, 1),
                                       dof(8, 0),  dof(8, 1),  dof(11, 0), dof(11, 1),
                                       dof(12, 0), /* 12y held */ dof(13, 0), dof(13, 1)};
    CHECK(detFDoFs(mesh) == expected);
  }
  TEST_CASE("detFDoFs: separate active regions / shared nodes counted once") {
    Mesh mesh = formCoord2D(4, 4, 4.0, 4.0);
    mesh.eInA.assign(mesh.nels(), 0);
    mesh.eInA[0] = mesh.eInA[5] = mesh.eInA[15] = 1;  // cells 0 and 5 share node 6
    const std::vector<int> fd = detFDoFs(mesh);
    CHECK(fd.size() == 2 * (4 + 3 + 4));  // nodes 0 1 5 6 | 7 11 12 | 18 19 23 24
    CHECK(std::is_sorted(fd.begin(), fd.end()));
    CHECK(std::adjacent_find(fd.begin(), fd.end()) == fd.end());
    for (int n : {0, 1, 5, 6, 7, 11, 12, 18, 19, 23, 24})
      for (int i = 0; i < nD; ++i) CHECK(std::binary_search(fd.begin(), fd.end(), dof(n, i)));
  }
}
