//--------------------------------------------------------------------------
// stiffnessPattern — the sparsity of Kt for one load step
//--------------------------------------------------------------------------
// A fast part (see docs/structure.md, "The fast parts"). [AMPLE] eq 30: Kt
// couples two nodes when a material point links both. The points link the
// same nodes in every Newton-Raphson pass of a load step, so
//   stiffnessPattern  builds the pattern once per step, from node buckets
//                     (each node column collects the distinct nodes of its
//                     points, marked as seen, then sorted), every value 0;
//   addToPattern      adds one point stiffness k_p into that pattern: a merge
//                     along each column of the point's ascending dofs;
//   addNodeBlocks     the same for a node-blocked pattern (nodeBlocked: every
//                     node pair a full 2 x 2 block, as stiffnessPattern makes
//                     it): 4 values per node pair, at the block positions that
//                     nodeBlockPositions found once per step (one search per
//                     node, a walk by node pairs).
// What it saves: assembling from triplets in every pass cost the 2^13-cell
// compaction 22.2 s against 15.7 s with the pattern refilled (measured when it
// was introduced), and no triplet list of 2 x (2 nn)^2 entries per point.
// Inputs:  nDoF · mpData (nIN, nn) | Kt (with the pattern) · d (n ascending
//          dofs of the point) or nIN (nn ascending nodes) and at · ke (n x n point stiffness)
// Outputs: Kt (nDoF x nDoF), compressed | val (Kt's values) += ke | at (nn x nn)
// Tests:   tests/test_detMPs.cpp
//--------------------------------------------------------------------------
#pragma once
#include "ample/mpData.h"
#include <Eigen/SparseCore>
#include <climits>

namespace ample {

SpMat stiffnessPattern(int nDoF, const std::vector<MaterialPoint>& mpData);
bool sameNodes(const MaterialPoint& a, const MaterialPoint& b);  // the same nn nodes nIN
// val: the values of Kt's pattern (Kt.valuePtr(), or a buffer of the same length)
// (only the columns [c0, c1), resp. those of the nodes [n0, n1): a thread's share)
void addToPattern(const SpMat& Kt, double* val, const int* d, int n,
                  const Eigen::Ref<const Eigen::MatrixXd>& ke, int c0 = 0, int c1 = INT_MAX);
bool nodeBlocked(const SpMat& Kt);
// at[nn b + a]: where the 2 x 2 block of nodes nIN[a], nIN[b] starts in Kt's values (column x of b)
void nodeBlockPositions(const SpMat& Kt, const int* nIN, int nn, int* at);
void addNodeBlocks(const SpMat& Kt, double* val, const int* nIN, int nn, const int* at,
                   const Eigen::Ref<const Eigen::MatrixXd>& ke, int n0 = 0, int n1 = INT_MAX);

}  // namespace ample
