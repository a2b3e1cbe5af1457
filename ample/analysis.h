//--------------------------------------------------------------------------
// analysis.h — one problem as the main loop sees it: mesh, points, settings
//--------------------------------------------------------------------------
// [AMPLE] sec 4: what setupGrid returns (the mesh and mpData of tables 3-4,
// the load steps, gravity and the Newton-Raphson settings), with the
// formulation and domain update of [Lagrangian], the two remedies (off by
// default), the implicit boundaries of [Boundaries] (none by default: nothing
// changes and nothing costs) and a setup's optional hooks at the start and
// end of a load step.
// Data only: the bottom layer with mpData.h (docs/structure.md). It names no type
// of an extension: the implicit boundaries' list is held opaque (std::any), for
// their room to read (ample/boundaries/boundary.h: boundariesOf).
//--------------------------------------------------------------------------
#pragma once
#include "mpData.h"
#include <any>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace ample {

struct Analysis {
  std::string name;                   // the setup's name (progress lines)
  Mesh mesh;                          // background grid with boundary conditions
  std::vector<MaterialPoint> mpData;  // material points
  int lstps = 1;                      // number of load steps
  double g = 0;                       // gravitational acceleration (m/s2), acting in -y
  // optional body force b(X, lf) per unit reference volume (N/m3) at a point's original
  // position X and load factor lf; the full force at lf, not scaled by the main loop
  // (detExtForce.h). Empty: none (the results of every other setup stay bit for bit)
  std::function<Vector2d(const Vector2d& X, double lf)> bodyForce;
  double tol = 1e-9;                  // Newton-Raphson tolerance on fErr (eq 35)
  int NRitMax = 10;                   // most Newton-Raphson passes per load step
  LinearSolver solver = LinearSolver::LU;  // Kt(fd,fd): SparseLU, or SimplicialLDLT when symmetric
  int substeps = 0;                   // halvings of a failed load step allowed (0: none)
  std::string widerGrid;              // the setting that widens the grid, e.g. "width=32" (a
                                      // point that leaves the grid: what to try; "" none)
  double ghost = 0;                   // ghost-penalty factor of the edge cells (0: none)
  double split = 0;                   // split GIMP points with lp(i) > split h(i) after a step (0: none)
  int lone = 2;                       // redundant lone-node dofs out of fd (detFDoFsLone): 0 never,
                                      // 1 every step, 2 from the first step that fails without it
  int ghostFrom = 0;                  // first load step the penalty was needed (0: not yet)
  int loneFrom = 0;                   // first load step the lone-node rule was needed (0: not yet)
  Formulation formulation = Formulation::UL;        // frame of equilibrium ([Lagrangian])
  DomainUpdate domainUpdate = DomainUpdate::Uii;    // GIMP domain update ([AMPLE] eq 34)
  Locking locking = Locking::None;                  // anti-locking (ample/locking/): none, F-bar
  bool geostatic = false;             // start from the K0 stress of the weight, the weight in full
  double K0 = 1;                      //   from step 1 (ample/initial/geostatic.h); sigma_h / sigma_v
  bool fem = false;                   // finite element mode: the mesh moves with the nodes (moveMesh)
  bool gridMoves = false;             // the setup rebuilds the grid between steps (beforeStep;
                                      // stretch, doughnut): postPro writes mesh_<lstp>.vtk
  std::any boundaries;                              // implicit boundaries ([Boundaries]), a
                                                    // std::vector<Boundary> (boundariesOf); empty: none
  Eigen::VectorXd frct;                             // reactions of the last converged step
  Eigen::VectorXd uvw;                              // its converged displacement increment
  std::vector<Vector2d> ibForce;                    // force of each implicit boundary on the body
  // optional work of a setup at the start / end of each load step (nullptr: none),
  // e.g. a grid that follows the body, boundary cells that change, a reaction history;
  // afterStep also gets the load factor lf reached at the step's end (Increment::lf1 of the
  // step, lstp / lstps; the halves of the substeps= remedy end there too): a load or a
  // prescribed displacement given as a total is that total times lf
  std::function<void(Analysis& an, int lstp)> beforeStep;
  std::function<void(Analysis& an, int lstp, double lf)> afterStep;
  std::vector<int> tagged;                          // points a setup marks for its hooks
  std::vector<std::vector<std::pair<std::string, double>>> history;  // rows for history.csv
};

}  // namespace ample
