//--------------------------------------------------------------------------
// detMPsFbar — detMPs with F-bar (UL, PC) or B-bar (SS) over the grid's cells
//--------------------------------------------------------------------------
// See detMPsFbar.h for the equations, inputs and outputs; docs/locking.md for
// the derivation of the tangent.
//--------------------------------------------------------------------------
#include "detMPsFbar.h"
#include "ample/basis/elemForMP.h"
#include "ample/meshes/cellSearch.h"
#include "ample/stiffness/formULstiff.h"
#include "ample/stiffness/tensorOps.h"
#include "ample/pointModel.h"
#include <cmath>

namespace ample {

namespace {

using Eigen::Matrix2d;
using Eigen::Matrix4d;
using Eigen::Vector4d;
using BMatrix = Eigen::Matrix<double, 4, nD * MAXN>;  // B(2k+l, 2b+k) = dS_b/dx_l: grad du = B u_p
using PointVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, nD * MAXN, 1>;  // 2 nn entries, no heap

struct FbarTerms {         // one point's share of fint and Kt
  Matrix4d A;               // A - Q (x) I: the tangent of the point's own nodes
  Vector4d Q;               // Q_ij, (i,j) -> 2i+j: the coupling to its cell's volume change
  Vector4d S;               // sigma_ij paired with dS/dx (eq 16)
  BMatrix B;                // spatial basis gradients (first 2 nn columns)
  double Vp;                // volume
};

// each cell's points and the union of their nodes (a point's cell: cellHolding)
struct Patches {
  std::vector<int> cell;                   // the cell of each point
  std::vector<int> start, points;          // cell c's points: points[start[c] .. start[c+1])
  std::vector<std::array<int, MAXN>> slot; // slot[p][v]: point p's node v in its cell's node list
  std::vector<int> nodeStart, nodes;       // cell c's nodes: nodes[nodeStart[c] .. nodeStart[c+1])
};


// grad du = sum_v du_v (x) dS_v/dX~, the in-plane block (eq 17 less I)
Matrix2d gradDu(const Eigen::VectorXd& uvw, const MaterialPoint& mp) {
  Matrix2d H = Matrix2d::Zero();
  for (int v = 0; v < mp.nn; ++v) H += uvw.segment<nD>(nD * mp.nIN[v]) * mp.dSvp.col(v).transpose();
  return H;
}

// the terms of a point with tangent A, stress sig, gradients dSx, volume Vp;
// Q = A:I / 2 - halfSig (halfSig: sigma / 2 for F-bar, 0 for B-bar)
FbarTerms terms(const Matrix4d& A, const Matrix2d& halfSig, const Matrix2d& sig,
                 const Eigen::Matrix<double, nD, MAXN>& dSx, double Vp, int nn) {
  FbarTerms t;
  for (int ij = 0; ij < 4; ++ij) t.Q(ij) = 0.5 * (A(ij, 0) + A(ij, 3)) - halfSig(ij / 2, ij % 2);
  t.A = A;
  t.A.col(0) -= t.Q;                                            // - Q_ij delta_kl
  t.A.col(3) -= t.Q;
  t.S << sig(0, 0), sig(0, 1), sig(1, 0), sig(1, 1);
  t.B.leftCols(nD * nn).setZero();
  for (int b = 0; b < nn; ++b)
    for (int k = 0; k < nD; ++k)
      for (int l = 0; l < nD; ++l) t.B(2 * k + l, 2 * b + k) = dSx(l, b);
  t.Vp = Vp;
  return t;
}

// F-bar (UL, PC): dF's in-plane block scaled to the cell's volume change dJbar
FbarTerms fbarPoint(const Matrix2d& dF, double dJbar, MaterialPoint& mp) {
  const double dJ = dF.determinant();
  Matrix3d dFbar = Matrix3d::Identity();
  dFbar.topLeftCorner<2, 2>() = std::sqrt(dJbar / dJ) * dF;
  const Matrix3d bEn = inPlaneExp(2.0 * strainToTensor(mp.epsEn));  // exp(2 eps_e,n), eq 9
  mp.F = dFbar * mp.Fn;                                         // eq 7
  const Matrix3d BeT = dFbar * bEn * dFbar.transpose();         // eq 8
  const InPlaneEigen eig = inPlaneEigen(BeT);
  const ConstOut cm = pointModel(tensorToStrain(0.5 * inPlaneLog(eig)), mp);  // eqs 10, 5, 11
  mp.epsE = cm.epsE;
  mp.sig = cm.Ksig / mp.F.determinant();                        // eq 6
  const Matrix4d A = formULstiff2D(mp.F, cm.D, mp.sig, BeT, dLogdB2D(eig));
  const Matrix2d sig = stressToTensor(mp.sig).topLeftCorner<2, 2>();
  Eigen::Matrix<double, nD, MAXN> dSx;
  dSx.leftCols(mp.nn) = dF.inverse().transpose() * mp.dSvp.leftCols(mp.nn);  // eq 18, the real dF
  return terms(A, 0.5 * sig, sig, dSx, dJ * mp.vp, mp.nn);     // v = dJ v^n, eq 15
}

// B-bar (SS): the trace of grad du replaced by the cell's average thetaBar
FbarTerms bbarPoint(const Matrix2d& H, double thetaBar, MaterialPoint& mp) {
  Matrix3d e = Matrix3d::Zero();
  e.topLeftCorner<2, 2>() = 0.5 * (H + H.transpose()) + 0.5 * (thetaBar - H.trace()) * Matrix2d::Identity();
  const ConstOut cm = pointModel(mp.epsEn + tensorToStrain(e), mp);  // [Boundaries] eqs 2-3
  mp.F = Matrix3d::Identity();
  mp.epsE = cm.epsE;
  mp.sig = cm.Ksig;
  return terms(elasticBlock2D(cm.D), Matrix2d::Zero(), stressToTensor(mp.sig).topLeftCorner<2, 2>(),
               mp.dSvp, mp.vp, mp.nn);
}

// the cells of the points, and each cell's nodes
Patches patchesOf(const Mesh& mesh, const std::vector<MaterialPoint>& mpData) {
  const int np = int(mpData.size()), nels = mesh.nels();
  Patches P;
  P.cell.resize(np);
  P.slot.resize(np);
  P.points.resize(np);
  P.start.assign(nels + 1, 0);
  for (int p = 0; p < np; ++p) P.start[(P.cell[p] = cellHolding(mesh, mpData[p].mpC)) + 1]++;
  for (int c = 0; c < nels; ++c) P.start[c + 1] += P.start[c];
  std::vector<int> next(P.start.begin(), P.start.end() - 1);
  for (int p = 0; p < np; ++p) P.points[next[P.cell[p]]++] = p;  // cell by cell, in point order
  P.nodeStart.assign(nels + 1, 0);
  for (int c = 0; c < nels; ++c) {
    for (int q = P.start[c]; q < P.start[c + 1]; ++q) {
      const MaterialPoint& mp = mpData[P.points[q]];
      for (int v = 0; v < mp.nn; ++v) {
        int s = P.nodeStart[c];
        while (s < int(P.nodes.size()) && P.nodes[s] != mp.nIN[v]) ++s;
        if (s == int(P.nodes.size())) P.nodes.push_back(mp.nIN[v]);
        P.slot[P.points[q]][v] = s - P.nodeStart[c];
      }
    }
    P.nodeStart[c + 1] = int(P.nodes.size());
  }
  return P;
}

}  // namespace

int cellHolding(const Mesh& mesh, const Vector2d& x) {
  std::array<int, MAXE> e;
  elemForMP(mesh, x, Vector2d::Zero(), e);                      // a standard point's cell
  return e[0];
}

std::string fbarRefusal(const Mesh& mesh, bool fem) {
  if (fem) return "locking=Fbar (1) averages over the cells of the regular grid; the finite element mode (fem=1) "
                  "moves a general mesh: use locking=none (0)";
  if (!mesh.regular())
    return std::string("locking=Fbar (1) averages over the cells of the regular grid; the background mesh is a ") +
           meshName(mesh) + ": use locking=none (0)";
  return "";
}

void detMPsFbar(const Mesh& mesh, const Eigen::VectorXd& uvw, std::vector<MaterialPoint>& mpData,
                Formulation form, DetMPsOut& out) {
  const bool SS = form == Formulation::SS;
  const int np = int(mpData.size()), nels = mesh.nels();
  const Patches P = patchesOf(mesh, mpData);
  std::vector<Matrix2d> G(np);                                  // dF (UL, PC) or grad du (SS)
  std::vector<double> bar(nels, 0.0), den(nels, 0.0);           // sum dJ v^n / sum v^n (SS: theta)
  for (int p = 0; p < np; ++p) {
    G[p] = gradDu(uvw, mpData[p]);
    if (!SS) G[p] += Matrix2d::Identity();
    bar[P.cell[p]] += (SS ? G[p].trace() : G[p].determinant()) * mpData[p].vp;
    den[P.cell[p]] += mpData[p].vp;
  }
  out.fint.setZero(uvw.size());
  std::vector<Eigen::Triplet<double>> Kt;
  std::vector<double> Kc, R, W;                                 // a cell's stiffness, R and W
  PointStiffness ke;
  Eigen::Matrix<double, 4, Eigen::Dynamic, 0, 4, nD * MAXN> AB;
  for (int c = 0; c < nels; ++c) {                              // the cells, each point of each
    const int n2 = nD * (P.nodeStart[c + 1] - P.nodeStart[c]);  // the cell's dofs
    if (n2 == 0) continue;
    Kc.assign(size_t(n2) * n2, 0.0), R.assign(n2, 0.0), W.assign(n2, 0.0);
    double V = 0.0;
    for (int q = P.start[c]; q < P.start[c + 1]; ++q) {         // the point loop
      const int p = P.points[q];
      MaterialPoint& mp = mpData[p];
      const FbarTerms t = SS ? bbarPoint(G[p], bar[c] / den[c], mp) : fbarPoint(G[p], bar[c] / den[c], mp);
      const int m2 = nD * mp.nn;
      const auto B = t.B.leftCols(m2);
      const PointVector f = t.Vp * B.transpose() * t.S;                                   // eq 16
      const PointVector r = t.Vp * B.transpose() * t.Q;                                   // B' Q v
      AB = t.A * B;
      ke.topLeftCorner(m2, m2).noalias() = t.Vp * B.transpose().lazyProduct(AB);          // eq 14
      for (int a = 0; a < m2; ++a) {                            // into the cell's K, R, W (eq 30)
        const int ra = nD * P.slot[p][a / nD] + a % nD;
        out.fint(dof(mp.nIN[a / nD], a % nD)) += f(a);
        R[ra] += r(a);
        W[ra] += t.Vp * t.B(3 * (a % nD), a);                   // v dS_v/dx_i
        for (int b = 0; b < m2; ++b) Kc[size_t(nD * P.slot[p][b / nD] + b % nD) * n2 + ra] += ke(a, b);
      }
      V += t.Vp;
    }
    const int* nodes = &P.nodes[P.nodeStart[c]];
    for (int b = 0; b < n2; ++b)                                // + R (x) W / V, then into Kt
      for (int a = 0; a < n2; ++a)
        Kt.emplace_back(dof(nodes[a / nD], a % nD), dof(nodes[b / nD], b % nD),
                        Kc[size_t(b) * n2 + a] + R[a] * W[b] / V);
  }
  out.Kt.resize(uvw.size(), uvw.size());
  out.Kt.setFromTriplets(Kt.begin(), Kt.end());
}

}  // namespace ample
