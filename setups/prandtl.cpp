//--------------------------------------------------------------------------
// prandtl — rigid strip footing on weightless von Mises (undrained) soil: q_u = (2 + pi) c_u
//--------------------------------------------------------------------------
// A strip footing of width B = 1 m on a weightless elastic-perfectly plastic layer,
// plane strain, von Mises (cmType=VM) with rho_y = sqrt(2 J2) = sqrt(2) c_u, the
// Tresca-matched undrained strength c_u of plane strain (`cu`). Half the domain:
// W = `width` B wide and D = `depth` B deep (5 B and 3 B: at 3 B x 2 B the locked plastic
// zone reaches the base and q is 4-7 % higher), a symmetry roller on the centre line
// (u_x = 0 at x = 0), the base fixed (y = 0), a roller on the far side (x = W).
// The top of the soil lies on the grid line y = D (square cells h = B / (2 nB):
// `nB` cells across the half footing) and the grid reaches two cells above it (the
// heave beside the footing). The footing is displacement control on the grid: the
// nodes of the line y = D with x <= B/2 move down push B / lstps per load step; with
// `rough=1` their u_x is held too (rough), with `rough=0` it is free (smooth).
// Exact (Prandtl 1920; Hill's mechanism for the smooth footing, the same load for a
// rough one on weightless soil): the limit pressure q_u = (2 + pi) c_u = 5.1416 c_u.
// The footing load is the sum of the footing nodes' vertical reactions (an.frct),
// twice that of the half model; q = load / B. Bilinear MPM locks for the isochoric
// plastic flow of von Mises, so q/c_u comes out above 5.14 and falls with h
// (docs/locking.md, "The benchmarks": locking=Fbar is the remedy this setup measures).
// E = 10 MPa and c_u = 10 kPa (E / c_u = 1000), nu = 0.3, small strain (SS), standard MPM
// points (mpType=MPM) by default.
// results: q_over_cu at the last step, its error (q/c_u) / (2 + pi) - 1, the peak
// q_max_over_cu (GIMP's load falls after it on fine grids: the top points' domains leave
// the line of footing nodes as they settle, docs/new-setup.md pitfall 3), the
// plateau (the change of q over the last quarter of the steps, relative to q), the
// elastic stiffness of the first step (q per settlement / (E / B)).
//   ample prandtl nB=8 rough=0 mpType=MPM
// Outputs: Analysis · results · history.csv: lstp, settlement_m, load_kN, q_over_cu
// Tests:   tests/test_benchmarks.cpp, CTest setup.prandtl
//--------------------------------------------------------------------------
#include "ample/errors.h"
#include "formCoord2D.h"
#include "setupHelpers.h"
#include <cmath>

namespace ample::prandtl {

static const double B = 1.0;                       // footing width (m)
static const double cuDefault = 10e3;              // c_u (Pa)

// the parameters and their defaults (their ranges and help: params)
struct Prandtl : Common {
  double cu = cuDefault;
  int nB = 4, width = 5, depth = 3;
  double push = 0.03;
  int rough = 1;
  Prandtl() {
    lstps = 15;
    cmType = CmType::VonMises;
    NRitMax = 30;                                  // GIMP at nB = 8 converges slowly in the last steps
    mpType = MpType::MPM;                          // MPM: GIMP's top domains cross the grid line as the
                                                   // surface heaves (locking=Fbar at nu = 0.3 stops there)
    formulation = Formulation::SS;                 // a limit load needs no large deformation
    E = 10e6;
    nu = 0.3;
    rhoY = std::sqrt(2.0) * cuDefault;
  }
};

Params params(Prandtl& p) {
  Params P = commonParams(p);
  param(P, "cu", p.cu).above(0)
      .help("undrained strength c_u (Pa): rho_y = sqrt(2) c_u (leave rhoY at its default)");
  param(P, "nB", p.nB).integer(1, 64).help("cells across the half footing B/2: h = B / (2 nB), B = 1 m");
  param(P, "width", p.width).integer(2, 20).help("half-domain width W / B (the mechanism reaches 1.5 B)");
  param(P, "depth", p.depth).integer(1, 20).help("domain depth D / B (the mechanism reaches 0.71 B)");
  param(P, "push", p.push).range(1e-4, 0.2).help("footing settlement / B at the last step");
  param(P, "rough", p.rough).integer(0, 1).help("1: the footing holds u_x (rough), 0: u_x free (smooth)");
  return P;
}

Analysis setupGrid(const Prandtl& p) {
  const double cu = p.cu;
  if (std::abs(p.rhoY - std::sqrt(2.0) * cuDefault) > 1e-9 * cuDefault)
    throw InputError("prandtl: the strength is given by cu (rho_y = sqrt(2) cu); leave rhoY at its default");
  const int nB = p.nB, nx = 2 * nB * p.width, ny = 2 * nB * p.depth;
  const double h = B / (2 * nB), W = nx * h, D = ny * h, eps = 1e-9 * h;
  Analysis an = baseAnalysis(p);
  an.mesh = formCoord2D(nx, ny + 2, W, D + 2 * h);         // two empty rows above the soil
  const double dv = -p.push * B / an.lstps;
  const bool rough = p.rough == 1;
  auto footing = [&](double X, double Y) { return std::abs(Y - D) < eps && X < B / 2 + eps; };
  fixDofs(an.mesh, 0, [&](double X, double Y) { return Y < D + eps && (X < eps || X > W - eps); });
  fixDofs(an.mesh, 0, [&](double X, double Y) { return Y < eps && X > eps && X < W - eps; });  // base
  fixDofs(an.mesh, 1, [&](double, double Y) { return Y < eps; });                              // base
  fixDofs(an.mesh, 1, footing, dv);                                                            // footing
  if (rough) fixDofs(an.mesh, 0, [&](double X, double Y) { return footing(X, Y) && X > eps; });
  fillBlock(an.mpData, Vector2d::Zero(), nx, ny, an.mesh.h, p, 0.0);   // weightless
  for (MaterialPoint& mp : an.mpData) mp.mCst.rhoY = std::sqrt(2.0) * cu;
  std::vector<int> nodes;                                              // the footing's nodes
  for (int n = 0; n < an.mesh.nodes(); ++n)
    if (footing(an.mesh.coord(n, 0), an.mesh.coord(n, 1))) nodes.push_back(n);
  an.afterStep = [=](Analysis& a, int lstp, double lf) {
    const double load = -2 * reactionOver(a.frct, nodes).sum(1);       // full footing (N/m)
    a.history.push_back({{"lstp", lstp}, {"settlement_m", -dv * a.lstps * lf},
                         {"load_kN", load / 1e3}, {"q_over_cu", load / B / cu}});
  };
  return an;
}

Results results(const Analysis& an, const Prandtl& p) {
  if (an.history.empty()) return {};
  const double exact = 2 + M_PI, q = an.history.back()[3].second;
  const size_t n = an.history.size(), k = n - std::max<size_t>(1, n / 4) - (n > 1 ? 1 : 0);
  const double plateau = (q - an.history[k][3].second) / q;
  double qMax = 0;                                            // the peak (GIMP falls after it)
  for (const auto& row : an.history) qMax = std::max(qMax, row[3].second);
  const auto& first = an.history.front();                     // q / settlement of the first step
  const double stiffness = first[3].second * p.cu / B / first[1].second / (p.E / B);
  return {{"q_over_cu", q}, {"exact", exact}, {"error", q / exact - 1}, {"q_max_over_cu", qMax},
          {"plateau_change", plateau}, {"first_step_stiffness", stiffness},
          {"points", double(an.mpData.size())}};
}

// this setup's line in the table of setups/setups.cpp
SetupCalls calls() { return {params, setupGrid, results}; }

}  // namespace ample::prandtl
