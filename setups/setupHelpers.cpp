//--------------------------------------------------------------------------
// setupHelpers — material point generation and boundary conditions for setups
//--------------------------------------------------------------------------
// See setupHelpers.h for inputs and outputs.
//--------------------------------------------------------------------------
#include "setupHelpers.h"
#include "ample/detMpPos.h"
#include "ample/shapefunc.h"

namespace ample {

Analysis baseAnalysis(const Params& P) {
  Analysis an;
  an.lstps = int(get(P, "lstps"));
  an.tol = get(P, "tol");
  an.NRitMax = int(get(P, "NRitMax"));
  an.substeps = int(get(P, "substeps"));
  an.ghost = get(P, "ghost");
  an.formulation = Formulation(int(get(P, "formulation")));
  an.domainUpdate = DomainUpdate(int(get(P, "domainUpdate")));
  return an;
}

void fillBlock(std::vector<MaterialPoint>& mpData, const Vector2d& corner, int nelsx, int nelsy,
               const Vector2d& h, const Params& P, double rho) {
  const int mp = int(get(P, "mp"));
  mpData.reserve(mpData.size() + size_t(nelsx) * nelsy * mp * mp);  // no growth by doubling
  const Eigen::MatrixX2d mpPos = detMpPos(mp);
  for (int ey = 0; ey < nelsy; ++ey)
    for (int ex = 0; ex < nelsx; ++ex) {
      const Vector2d c0 = corner + Vector2d(ex * h(0), ey * h(1));  // cell lower-left corner
      Eigen::Matrix<double, 4, 2> eC;                              // cell corner coordinates
      eC << c0(0), c0(1), c0(0) + h(0), c0(1), c0(0) + h(0), c0(1) + h(1), c0(0), c0(1) + h(1);
      for (int q = 0; q < mpPos.rows(); ++q) {
        MaterialPoint pt;
        pt.mpType = MpType(int(get(P, "mpType")));
        pt.cmType = CmType(int(get(P, "cmType")));
        pt.mpC = (shapefunc(mpPos.row(q).transpose()).transpose() * eC).transpose();
        pt.X0 = pt.mpC;
        pt.lp0 = h / (2.0 * mp);
        pt.vp0 = pt.vp = 4.0 * pt.lp0(0) * pt.lp0(1);
        pt.st0 = pt.st = (2.0 * pt.lp0).asDiagonal();      // CPDI1 domain vectors s, t
        for (int c = 0; c < 4; ++c)                         // rectangle corners (CPDI2)
          pt.xc.col(c) = pt.mpC + Vector2d((c == 1 || c == 2) ? pt.lp0(0) : -pt.lp0(0),
                                           (c >= 2) ? pt.lp0(1) : -pt.lp0(1));
        if (pt.mpType == MpType::MPM) pt.lp0.setZero();  // standard MPM carries no domain
        pt.lp = pt.lp0;
        pt.mpM = rho * pt.vp0;
        pt.mCst << get(P, "E"), get(P, "nu"), get(P, "rhoY");
        mpData.push_back(pt);
      }
    }
}

void fixDofs(Mesh& mesh, int i, const std::function<bool(double, double)>& where,
             double value) {
  for (int n = 0; n < mesh.nodes(); ++n)
    if (where(mesh.coord(n, 0), mesh.coord(n, 1))) mesh.bc.push_back({dof(n, i), value});
}

}  // namespace ample
