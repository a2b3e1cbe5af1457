//--------------------------------------------------------------------------
// linSolve — linear solve for the displacement and reaction increments
//--------------------------------------------------------------------------
// Seed 002 eq 29. See linSolve.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "linSolve.h"
#include "errors.h"
#include <Eigen/SparseLU>

namespace ample {

LinSolveOut linSolve(const std::vector<BC>& bc, const SpMat& Kt, const Eigen::VectorXd& oobf,
                     int NRit, const std::vector<int>& fd) {
  const int nDoF = int(oobf.size()), nfd = int(fd.size());
  LinSolveOut out{Eigen::VectorXd::Zero(nDoF), Eigen::VectorXd::Zero(nDoF)};
  if (NRit == 0) return out;  // first pass only builds Kt and fint
  if (NRit == 1)
    for (const BC& c : bc) out.duvw(c.dof) = c.value;  // prescribed increments

  const Eigen::VectorXd Kd = Kt * out.duvw;             // Kt(:,bc) duvw(bc)
  if (nfd == 0) {                                       // every active dof is prescribed
    for (const BC& c : bc) out.drct(c.dof) = Kd(c.dof) - oobf(c.dof);
    return out;
  }
  std::vector<int> freeIdx(nDoF, -1);                   // global dof -> row of Kt(fd,fd)
  for (int r = 0; r < nfd; ++r) freeIdx[fd[r]] = r;
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(Kt.nonZeros());
  for (int c = 0; c < Kt.outerSize(); ++c)
    if (freeIdx[c] >= 0)
      for (SpMat::InnerIterator it(Kt, c); it; ++it)
        if (freeIdx[it.row()] >= 0) trip.emplace_back(freeIdx[it.row()], freeIdx[c], it.value());
  SpMat Kff(nfd, nfd);
  Kff.setFromTriplets(trip.begin(), trip.end());

  Eigen::VectorXd rhs(nfd);
  for (int r = 0; r < nfd; ++r) rhs(r) = oobf(fd[r]) - Kd(fd[r]);

  Eigen::SparseLU<SpMat, Eigen::COLAMDOrdering<int>> solver;
  solver.compute(Kff);
  if (solver.info() != Eigen::Success)
    throw RunError("SparseLU could not factorise the stiffness Kt(fd,fd) (" +
                   solver.lastErrorMessage() + "): the problem is singular, e.g. a rigid-body "
                   "mode without enough boundary conditions or a nearly empty cell");
  const Eigen::VectorXd x = solver.solve(rhs);
  for (int r = 0; r < nfd; ++r) out.duvw(fd[r]) = x(r);

  const Eigen::VectorXd Ku = Kt * out.duvw;
  for (const BC& c : bc) out.drct(c.dof) = Ku(c.dof) - oobf(c.dof);
  return out;
}

}  // namespace ample
