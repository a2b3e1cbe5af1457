//--------------------------------------------------------------------------
// linSolve — linear solve for the displacement and reaction increments
//--------------------------------------------------------------------------
// [AMPLE] eq 29. See linSolve.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "linSolve.h"
#include "errors.h"
#include "constitutive/exercise.h"
#include <Eigen/SparseLU>
#include <string>

namespace ample {

static SpMat freeBlock(const SpMat& Kt, const std::vector<int>& fd);

LinSolveOut linSolve(const std::vector<BC>& bc, const SpMat& Kt, const Eigen::VectorXd& oobf,
                     int NRit, const std::vector<int>& fd, const FreeSolve& solver) {
  // BEGIN EXERCISE linSolve
  const int nDoF = int(oobf.size()), nfd = int(fd.size());
  LinSolveOut out{Eigen::VectorXd::Zero(nDoF), Eigen::VectorXd::Zero(nDoF)};
  if (NRit == 0) return out;                            // first pass only builds Kt and fint
  if (NRit == 1)
    for (const BC& c : bc) out.duvw(c.dof) = c.value;   // prescribed increments
  const Eigen::VectorXd Kd = Kt * out.duvw;             // Kt(:,bc) duvw(bc)
  if (nfd > 0) {
    Eigen::VectorXd rhs(nfd);
    for (int r = 0; r < nfd; ++r) rhs(r) = oobf(fd[r]) - Kd(fd[r]);
    const Eigen::VectorXd x = solver.solveFree(Kt, fd, rhs, NRit);  // Kt(fd,fd) \ rhs
    for (int r = 0; r < nfd; ++r) out.duvw(fd[r]) = x(r);
  }
  const Eigen::VectorXd Ku = Kt * out.duvw;
  for (const BC& c : bc) out.drct(c.dof) = Ku(c.dof) - oobf(c.dof);
  return out;
  // END EXERCISE
}

Eigen::VectorXd solveFree(const SpMat& Kt, const std::vector<int>& fd, const Eigen::VectorXd& rhs, int /*NRit*/) {
  const SpMat Kff = freeBlock(Kt, fd);                  // Kt(fd,fd)
  Eigen::SparseLU<SpMat, Eigen::COLAMDOrdering<int>> lu(Kff);
  if (lu.info() != Eigen::Success)
    throw RunError("SparseLU could not factorise the stiffness Kt(fd,fd) (" + lu.lastErrorMessage() +
                   "): the problem is singular, e.g. a rigid-body mode without enough boundary "
                   "conditions or a nearly empty cell", Failure::Singular);
  const Eigen::VectorXd x = lu.solve(rhs);
  checkSolved(Kff * x - rhs, rhs);
  return x;
}

void checkSolved(const Eigen::VectorXd& residual, const Eigen::VectorXd& rhs) {
  const double res = residual.norm(), scale = rhs.norm() + 1e-300;
  if (!(res <= 1e-3 * scale))                           // a zero pivot: no solution exists
    throw RunError("the stiffness Kt(fd,fd) is singular (linear solve residual " +
                   std::to_string(res / scale) + " of the right-hand side): a rigid-body mode "
                   "without enough boundary conditions, or a nearly empty cell", Failure::Singular);
}

// Kt(fd,fd): the entries of Kt in free rows and columns, renumbered 0..nfd-1 (fd ascending)
static SpMat freeBlock(const SpMat& Kt, const std::vector<int>& fd) {
  std::vector<int> free(Kt.rows(), -1);                 // dof -> its row in Kt(fd,fd), or -1
  for (size_t r = 0; r < fd.size(); ++r) free[fd[r]] = int(r);
  std::vector<Eigen::Triplet<double>> entries;
  for (int c : fd)
    for (SpMat::InnerIterator it(Kt, c); it; ++it)
      if (free[it.row()] >= 0) entries.emplace_back(free[it.row()], free[c], it.value());
  SpMat Kff(int(fd.size()), int(fd.size()));
  Kff.setFromTriplets(entries.begin(), entries.end());
  return Kff;
}

}  // namespace ample
