//--------------------------------------------------------------------------
// detMPsFast — the point loop of an optimised build: the same equations, faster
//--------------------------------------------------------------------------
// Replaces the point loop (detMPs, ample/detMPs.h; detMPsForm for PC and SS,
// ample/formulations/) as a whole where the program chooses it
// (RunOptions::pointLoop, chosen in program/run.cpp), with no equation of its
// own: addPoint (addPoint.h) for every point, the unrolled sums of eqs 14 and
// 16. What it adds:
//   runs of fewer than fastFrom() points (fastFrom.h): the plain loop itself;
//   exp(2 eps_e,n) of every point once per load step (PointLoopPlan::bEn, eq 9);
//   node-blocked assembly (addNodeBlocks) where Kt's pattern allows it, each
//   point's blocks found in the pattern once per load step (PointLoopPlan::at);
//   a prefetch of the next points' memory;
//   OpenMP threads (pointShares.h): thread t owns a range of nodes, their
//   rows of fint and columns of Kt, and adds every point that links one of
//   them in point order; a point in two ranges is computed by both, its
//   state written by the owner of its first node: bit for bit the serial
//   loop on any number of threads.
// Inputs/outputs: those of detMPs; out.plan (PointLoopPlan) kept for the step.
// Tests:   tests/test_detMPs.cpp (1-4 threads, bit for bit), tests/test_pointLoops.cpp
//          (against detMPs and detMPsForm, within 1e-12)
//--------------------------------------------------------------------------
#pragma once
#include "ample/detMPs.h"
#include "fastFrom.h"

namespace ample {

struct ThreadShares;                          // the threads' points (detMPsFast.cpp)

struct PointLoopPlan {                        // what detMPsFast keeps for a load step (DetMPsOut::plan)
  std::vector<Matrix3d> bEn;                  // exp(2 eps_e,n) of each point (eq 9; UL, PC)
  long patternNnz = -1;                       // the pattern of Kt the entries below were found for
  bool blocked = false;                       // it is node-blocked (nodeBlocked)
  std::vector<long> from;                     // point p's node blocks start at at[from[p]] (nn x nn)
  std::vector<int> at;                        // (nodeBlockPositions; when blocked)
  std::shared_ptr<ThreadShares> threads;      // on more than one thread
};

void detMPsFast(const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData, Formulation form,
                DetMPsOut& out);

// exp(2 eps_e,n) of every point (eq 9), once per load step
std::vector<Matrix3d> elasticLeftCGs(const std::vector<MaterialPoint>& mpData);

}  // namespace ample
