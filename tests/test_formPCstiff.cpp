// Tests of formPCstiff ([Lagrangian] appendix A.2), the consistent tangent of the
// previously converged (PC) formulation: at the material level against central
// differences of P~(dF) = tau dF^-T / Jn, and assembled by detMPsForm (PC)
// against central differences of the PC internal force. PC and UL describe the
// same equilibrium in two frames, so their internal forces (and hence their
// tangents) agree for the same increment.
#include "setups/program/run.h"
#include "ample/detFDoFs.h"
#include "ample/remedies/loneNodes.h"
#include "ample/formulations/detMPsForm.h"
#include "ample/elemMPinfo.h"
#include "ample/stiffness/formPCstiff.h"
#include "ample/stiffness/tensorOps.h"
#include "constitutive/Hooke3d.h"
#include "constitutive/VMconst.h"
#include "testProblems.h"
#include <doctest/doctest.h>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

using namespace ample;

namespace {
double pcTangentError(Analysis& an, const Eigen::VectorXd& uvw) {
  return testing::tangentError(an, uvw, Formulation::PC);
}

// deviatoric norm of the Kirchhoff stress of every point (after a detMPs call)
void requireAllYielding(const std::vector<MaterialPoint>& mpData) {
  for (const MaterialPoint& mp : mpData) {
    const Vector6d tau = mp.sig * mp.F.determinant();
    const double p = tau.head<3>().sum() / 3.0;
    const double rho = std::sqrt((tau.head<3>().array() - p).square().sum() +
                                 2.0 * tau.tail<3>().squaredNorm());
    REQUIRE(rho == doctest::Approx(mp.mCst.rhoY).epsilon(1e-10));
  }
}

Analysis prestrainedBlock(MpType t, CmType c) {
  Analysis an = testing::smallBlock(t, c);
  testing::prestrain(an.mpData, 7);
  for (MaterialPoint& mp : an.mpData) {
    mp.mpC += Vector2d(0.13, -0.07);  // GIMP domains straddle cell edges
    mp.vp = mp.Fn.determinant() * mp.vp0;  // V^n consistent with Fn
  }
  elemMPinfo(an.mesh, an.mpData);
  return an;
}

// material-level PC stress P~(dF) = tau(dF) dF^-T / Jn, with the constitutive model
struct PCState {
  Matrix3d P, tau, BeT;
  Matrix6d D;
};
PCState pcStress(const Matrix3d& dF, const Matrix3d& bEn, double Jn, CmType cm,
                 const MaterialConstants& mCst) {
  PCState s;
  s.BeT = dF * bEn * dF.transpose();
  const Vector6d epsTr = tensorToStrain(0.5 * symLog(s.BeT));
  const ConstOut out = (cm == CmType::Elastic) ? Hooke3d(epsTr, mCst) : VMconst(epsTr, mCst);
  s.D = out.D;
  s.tau = stressToTensor(out.Ksig);
  s.P = s.tau * dF.inverse().transpose() / Jn;
  return s;
}

// the standard-MPM beam at h = 0.5 m run to its end with formulation f
Analysis mpmBeam(Formulation f, const std::vector<std::pair<std::string, double>>& set) {
  const Setup* s = findSetup("beam");
  Params P = s->params();
  setParam(P, "a", 1);
  setParam(P, "mpType", int(MpType::MPM));
  setParam(P, "formulation", int(f));
  for (const auto& kv : set) setParam(P, kv.first, kv.second);
  Analysis an = s->setupGrid(P);
  if (P.named("ghost").value() > 0) an.ghostFrom = 1;  // the penalty on from the start, not after a failure
  RunLog log;
  solveRun(an, log);
  return an;
}
}  // namespace

TEST_SUITE("formPCstiff") {
  TEST_CASE("formPCstiff: A~ equals central differences of P~ = tau dF^-T / Jn (all 9 components)") {
    const MaterialConstants mCst{1e6, 0.3, 2e3};
    Matrix3d Fn;
    Fn << 1.04, 0.03, 0, -0.02, 0.97, 0, 0, 0, 1;
    const double Jn = Fn.determinant();
    for (CmType cm : {CmType::Elastic, CmType::VonMises}) {
      CAPTURE(int(cm));
      Vector6d epsEn;  // VM: a large deviatoric elastic strain so the trial state yields
      if (cm == CmType::Elastic) epsEn << 1e-3, -5e-4, 2e-4, 8e-4, 0, 0;
      else epsEn << 6e-3, -4e-3, -1e-3, 5e-3, 0, 0;
      const Matrix3d bEn = symExp(2.0 * strainToTensor(epsEn));
      Matrix3d dF;
      dF << 1.02, 0.015, 0.0, -0.01, 0.985, 0.0, 0.0, 0.0, 1.0;
      const PCState s0 = pcStress(dF, bEn, Jn, cm, mCst);
      if (cm == CmType::VonMises) {  // the base state and the stencil are plastic
        const double p = s0.tau.trace() / 3.0;
        const double rho = (s0.tau - p * Matrix3d::Identity()).norm();
        REQUIRE(rho == doctest::Approx(mCst.rhoY).epsilon(1e-10));
      }
      const Matrix9d A = formPCstiff(dF, Jn, s0.D, s0.tau, bEn, s0.BeT);
      Matrix9d Afd;
      const double d = 1e-7;
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) {
          Matrix3d dFp = dF, dFm = dF;
          dFp(k, l) += d;
          dFm(k, l) -= d;
          const Matrix3d dP = (pcStress(dFp, bEn, Jn, cm, mCst).P - pcStress(dFm, bEn, Jn, cm, mCst).P) / (2 * d);
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) Afd(3 * i + j, 3 * k + l) = dP(i, j);
        }
      CHECK((A - Afd).norm() / A.norm() < 1e-6);
    }
  }

  TEST_CASE("formPCstiff: detMPs(PC) tangent equals central differences of the PC internal force") {
    for (MpType t : {MpType::MPM, MpType::GIMP})
      for (CmType c : {CmType::Elastic, CmType::VonMises}) {
        CAPTURE(int(t));
        CAPTURE(int(c));
        Analysis an = prestrainedBlock(t, c);
        const Eigen::VectorXd uvw = testing::randomUvw(an, 0.02, 11);
        if (c == CmType::VonMises) {  // every point must be yielding for a smooth FD
          detMPsOf(uvw, an.mpData, Formulation::PC);
          requireAllYielding(an.mpData);
        }
        CHECK(pcTangentError(an, uvw) < 1e-6);
      }
  }

  TEST_CASE("formPCstiff: PC and UL internal forces are equal for the same increment") {
    for (MpType t : {MpType::MPM, MpType::GIMP})
      for (CmType c : {CmType::Elastic, CmType::VonMises}) {
        CAPTURE(int(t));
        CAPTURE(int(c));
        Analysis an = prestrainedBlock(t, c);
        const Eigen::VectorXd uvw = testing::randomUvw(an, 0.02, 11);
        const Eigen::VectorXd fPC = detMPsOf(uvw, an.mpData, Formulation::PC).fint;
        const Eigen::VectorXd fUL = detMPs(uvw, an.mpData, Formulation::UL).fint;
        REQUIRE(fUL.norm() > 0.0);
        CHECK((fPC - fUL).norm() <= 1e-12 * fUL.norm());
      }
  }

  TEST_CASE("formPCstiff: PC and UL tangents are equal (derivatives of the same internal force)") {
    for (MpType t : {MpType::MPM, MpType::GIMP})
      for (CmType c : {CmType::Elastic, CmType::VonMises}) {
        CAPTURE(int(t));
        CAPTURE(int(c));
        Analysis an = prestrainedBlock(t, c);
        const Eigen::VectorXd uvw = testing::randomUvw(an, 0.02, 11);
        const Eigen::MatrixXd KPC = Eigen::MatrixXd(detMPsOf(uvw, an.mpData, Formulation::PC).Kt);
        const Eigen::MatrixXd KUL = Eigen::MatrixXd(detMPs(uvw, an.mpData, Formulation::UL).Kt);
        CHECK((KPC - KUL).norm() <= 1e-10 * KUL.norm());
      }
  }

  TEST_CASE("formPCstiff: zero increment from an unstressed state gives the small-strain stiffness") {
    // dF = I, Jn = 1, b_e,n = I: A~_ijkl = D_ijkl (isotropic Hooke in tensor form)
    const MaterialConstants mCst{1e6, 0.3, 2e3};
    const Matrix6d D = elasticStiffness(mCst.E, mCst.nu);
    const Matrix3d I = Matrix3d::Identity();
    const Matrix9d A = formPCstiff(I, 1.0, D, Matrix3d::Zero(), I, I);
    const double lam = mCst.E * mCst.nu / ((1 + mCst.nu) * (1 - 2 * mCst.nu));
    const double G = mCst.E / (2 * (1 + mCst.nu));
    Matrix9d Aref = Matrix9d::Zero();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l)
            Aref(3 * i + j, 3 * k + l) = lam * (i == j) * (k == l) + G * ((i == k) * (j == l) + (i == l) * (j == k));
    CHECK((A - Aref).norm() <= 1e-12 * Aref.norm());
  }
}

TEST_SUITE("formPCstiff") {
  TEST_CASE("formPCstiff2D: equals the in-plane block of formPCstiff in plane strain") {
    Matrix3d dF, bEn;
    dF << 1.1, 0.2, 0, -0.15, 0.95, 0, 0, 0, 1;
    bEn << 1.2, -0.1, 0, -0.1, 0.9, 0, 0, 0, 1.05;
    const Matrix3d BeT = dF * bEn * dF.transpose();
    Matrix3d tau;
    tau << 2e3, 5e2, 0, 5e2, -1e3, 0, 0, 0, 3e2;
    const Matrix6d D = elasticStiffness(1e6, 0.3);
    const Matrix9d A9 = formPCstiff(dF, 1.3, D, tau, bEn, BeT);
    const Eigen::Matrix4d A4 = formPCstiff2D(dF, 1.3, D, tau, bEn, BeT);
    for (int p = 0; p < 4; ++p)
      for (int q = 0; q < 4; ++q)
        CHECK(std::abs(A4(p, q) - A9(3 * (p / 2) + p % 2, 3 * (q / 2) + q % 2)) <= 1e-10 * A9.norm());
  }
}

// With standard MPM the 6x6 beam stops in load step 11 (h = 0.5 m) with PC
// and in step 7 (h = 0.25 m) while UL completes. PC is not at fault: PC and UL give the same
// fint and Kt at every iterate. In load step 11 (h = 0.5 m) a point at the free tip's corner
// is the only point on two nodes of its cell; equilibrium of those two nodes makes its stress
// zero, and any rotation of that stress-free point is then an equilibrium state too: Kt has a
// zero eigenvalue (1e-17 of the largest). The Newton step along that mode is roundoff over
// roundoff (0.02 m with UL, 7.4 m with PC from the same state in step 11), and a large one
// costs more than NRitMax = 10 passes — for either formulation (from PC's state at h = 0.25 m
// UL fails step 7 too). The ghost penalty removes the mode: then PC and UL agree to roundoff.
TEST_SUITE("formPCstiff") {
  TEST_CASE("formPCstiff: MPM beam step 11 / PC equals UL but Kt has the zero mode of a lone stress-free point") {
    Params P = findSetup("beam")->params();  // UL: the converged increment of load step 11
    setParam(P, "a", 1);
    setParam(P, "mpType", int(MpType::MPM));
    Analysis an = findSetup("beam")->setupGrid(P);
    std::vector<MaterialPoint> start;                         // the points at the start of step 11
    an.beforeStep = [&start](Analysis& a, int lstp) { if (lstp == 11) start = a.mpData; };
    RunLog log;
    solveRun(an, log, RunOptions{"", 0, true, 11});              // steps 1 to 11
    const Eigen::VectorXd uvw = an.uvw;                       // the converged increment of step 11
    elemMPinfo(an.mesh, start);                               // the basis of step 11
    an.mpData = start;
    std::vector<MaterialPoint> mpUL = an.mpData, mpPC = an.mpData;
    const DetMPsOut ul = detMPs(uvw, mpUL, Formulation::UL), pc = detMPsOf(uvw, mpPC, Formulation::PC);
    const Eigen::MatrixXd K(ul.Kt), KPC(pc.Kt);
    CHECK((pc.fint - ul.fint).norm() <= 1e-13 * ul.fint.norm());
    CHECK((KPC - K).norm() <= 1e-13 * K.norm());

    std::vector<int> touching(an.mesh.nodes(), 0), lone;  // points on each node
    for (const MaterialPoint& mp : an.mpData)
      for (int v = 0; v < mp.nn; ++v) ++touching[mp.nIN[v]];
    double sMax = 0;
    for (const MaterialPoint& mp : mpUL) sMax = std::max(sMax, mp.sig.cwiseAbs().maxCoeff());
    for (size_t p = 0; p < mpUL.size(); ++p) {
      int alone = 0;
      for (int v = 0; v < mpUL[p].nn; ++v) alone += (touching[mpUL[p].nIN[v]] == 1);
      if (alone >= 2) lone.push_back(int(p));
    }
    REQUIRE(lone.size() == 1);                                  // the corner point at the tip
    CHECK(mpUL[lone[0]].sig.cwiseAbs().maxCoeff() <= 1e-8 * sMax);  // stress free (to tol)

    const std::vector<int> fd = detFDoFsLone(an.mesh, an.mpData);
    Eigen::MatrixXd Kff(fd.size(), fd.size());
    for (size_t i = 0; i < fd.size(); ++i)
      for (size_t j = 0; j < fd.size(); ++j) Kff(i, j) = K(fd[i], fd[j]);
    const Eigen::VectorXd lam = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(
        0.5 * (Kff + Kff.transpose()), Eigen::EigenvaluesOnly).eigenvalues();
    const double lMax = lam.cwiseAbs().maxCoeff();
    CHECK(std::abs(lam(0)) <= 1e-14 * lMax);                    // one zero-energy mode
    CHECK(lam(1) >= 1e-7 * lMax);                               // and only one
  }

  TEST_CASE("formPCstiff: MPM beam at h = 0.5 m / with the ghost penalty UL and PC give the same points to 1e-10") {
    const std::vector<std::pair<std::string, double>> set = {{"ghost", 0.001}};
    const Analysis ul = mpmBeam(Formulation::UL, set), pc = mpmBeam(Formulation::PC, set);
    double sMax = 0, dS = 0, dX = 0;
    for (size_t p = 0; p < ul.mpData.size(); ++p) {
      sMax = std::max(sMax, ul.mpData[p].sig.cwiseAbs().maxCoeff());
      dS = std::max(dS, (ul.mpData[p].sig - pc.mpData[p].sig).cwiseAbs().maxCoeff());
      dX = std::max(dX, (ul.mpData[p].mpC - pc.mpData[p].mpC).cwiseAbs().maxCoeff());
    }
    CHECK(dS <= 1e-10 * sMax);   // measured 5e-14
    CHECK(dX <= 1e-10 * 10.0);   // relative to the beam length (measured 1e-14 m)
  }

  TEST_CASE("formPCstiff: MPM beam at h = 0.5 m / without a remedy UL and PC give the same tip to 1e-5 with NRitMax = 40") {
    const std::vector<std::pair<std::string, double>> set = {{"NRitMax", 40}};
    const Analysis ul = mpmBeam(Formulation::UL, set), pc = mpmBeam(Formulation::PC, set);
    const Params P = findSetup("beam")->params();
    const Results ru = findSetup("beam")->results(ul, P), rp = findSetup("beam")->results(pc, P);
    CHECK(std::abs(rp[0].second / ru[0].second - 1.0) <= 1e-5);  // tip u (measured 5e-7)
    CHECK(std::abs(rp[1].second / ru[1].second - 1.0) <= 1e-5);  // tip v (measured 8e-8)
  }
}
