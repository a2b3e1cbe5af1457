//--------------------------------------------------------------------------
// solver_bench — orderings of Eigen's sparse solvers on the collapse's Kt(fd,fd)
//--------------------------------------------------------------------------
// "The sparse solve" (docs/scaling.md). For the collapse ([AMPLE]
// sec 5.3) at grid refinement a (h = 2 m / a) with mp x mp points per cell it
// builds the free stiffness Kt(fd,fd) of load step 1 (or later) as the main loop does
// (setupGrid, elemMPinfo, detFDoFs, stiffnessPattern, detMPs at uvw = 0: the
// elastic tangent; --after: a later step, see collapseKff) and solves
// Kt(fd,fd) x = b with b = Kt(fd,fd) x*, x*_i = sin(i + 1), by each solver:
//   LU_COLAMD, LU_AMD              Eigen's SparseLU with that column ordering
//   LU_AMD_T0.1                    SparseLU, AMD, diagonal pivots down to 0.1 of the largest
//   LU_AMD_SYM                     SparseLU, AMD, in SuperLU's symmetric mode (diagonal
//                                  pivots down to 1e-3 of the column's largest)
//   LDLT_AMD                       Eigen's SimplicialLDLT with AMD (solver=LDLT)
// (MUMPS, solver=MUMPS, is measured by whole runs: ample_bench's scaling suites.)
// Each (size, solver) runs --reps times, each in a child process (fork) so
// that its peak memory (wait4's ru_maxrss, which includes the parent's pages
// holding Kt(fd,fd): `base_MB`) and its failures are its own. A child that
// passes --limit seconds is stopped (did not finish); one that needs more
// than --mem GB of address space fails to allocate (did not fit).
// Usage:   solver_bench [--a 2,4,8,16,32] [--mp 6] [--after 0] [--reps 3] [--cases A,B]
//                       [--limit 900] [--mem 12] [--out docs/results/ordering.csv]
// --after N: the Kt(fd,fd) at the start of load step N + 1 (N steps solved first).
// Outputs: one CSV row per run: a, after_steps, nmp, nfd, nnz of Kt(fd,fd), solver,
//          repetition, status (ok / time limit / no memory / failed), analyse_s,
//          factorise_s, solve_s, fill (nonzeros of L+U or of L), factor_MB
//          (fill x 12 bytes: a double and an index), peak_MB, base_MB, the
//          relative error |x - x*| / |x*| and residual |K x - b| / |b|
//          (docs/results/ordering*.csv also hold runs of the retired METIS and
//          SuiteSparse cases, with a last column ordering_chosen)
// Build:   cmake --build --preset release --target solver_bench
//--------------------------------------------------------------------------
#include "setups/program/cli.h"
#include "ample/detFDoFs.h"
#include "ample/remedies/loneNodes.h"
#include "ample/detMPs.h"
#include "ample/elemMPinfo.h"
#include "ample/solver/freeSystem.h"
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <malloc.h>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <new>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

using ample::SpMat;

double now() {
  timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

// resident memory of this process now (MB), from /proc/self/statm
double residentMB() {
  long pages = 0, resident = 0;
  std::ifstream("/proc/self/statm") >> pages >> resident;
  return resident * double(sysconf(_SC_PAGESIZE)) / 1048576.0;
}

// what one solve measured
struct Timing {
  double analyse = 0, factorise = 0, solve = 0;  // seconds
  double fill = 0;                               // nonzeros of L+U (LU) or of L (LL^T, LDL^T)
  double error = 0, residual = 0;                // |x - x*| / |x*|, |K x - b| / |b|
};

//--------------------------------------------------------------------------
// timeSolver — analyse, factorise and solve K x = b with one Eigen-style solver
//--------------------------------------------------------------------------
// Inputs:  solver (analyzePattern / factorize / solve / info) · K · b · x*
//          fillOf(solver): the nonzeros of its factor(s)
// Outputs: Timing; throws std::runtime_error when a phase reports failure
//--------------------------------------------------------------------------
template <class Solver>
Timing timeSolver(Solver& s, const SpMat& K, const Eigen::VectorXd& b, const Eigen::VectorXd& xStar,
                  const std::function<double(Solver&)>& fillOf) {
  Timing t;
  double t0 = now();
  s.analyzePattern(K);
  t.analyse = now() - t0;
  t0 = now();
  s.factorize(K);
  t.factorise = now() - t0;
  if (s.info() != Eigen::Success) throw std::runtime_error("factorisation failed");
  t0 = now();
  const Eigen::VectorXd x = s.solve(b);
  t.solve = now() - t0;
  t.error = (x - xStar).norm() / xStar.norm();
  t.residual = (K * x - b).norm() / b.norm();
  t.fill = fillOf(s);
  return t;
}

template <class LU>
double luFill(LU& s) { return double(s.nnzL() + s.nnzU()); }
template <class LDLT>
double ldltFill(LDLT& s) { return double(s.matrixL().nestedExpression().nonZeros()); }

//--------------------------------------------------------------------------
// runCase — one named solver on K (in the child process)
//--------------------------------------------------------------------------
// Inputs:  name (the list in the header above) · K · b · x*
// Outputs: Timing; throws std::runtime_error for a name not in the list
//--------------------------------------------------------------------------
Timing runCase(const std::string& name, const SpMat& K, const Eigen::VectorXd& b, const Eigen::VectorXd& xStar) {
  using namespace Eigen;
  if (name == "LU_COLAMD") {
    SparseLU<SpMat, COLAMDOrdering<int>> s;
    return timeSolver<decltype(s)>(s, K, b, xStar, luFill<decltype(s)>);
  }
  if (name == "LU_AMD") {
    SparseLU<SpMat, AMDOrdering<int>> s;
    return timeSolver<decltype(s)>(s, K, b, xStar, luFill<decltype(s)>);
  }
  if (name == "LU_AMD_T0.1") {  // diagonal pivots kept down to 0.1 of the column's largest
    SparseLU<SpMat, AMDOrdering<int>> s;
    s.setPivotThreshold(0.1);
    return timeSolver<decltype(s)>(s, K, b, xStar, luFill<decltype(s)>);
  }
  if (name == "LU_AMD_SYM") {  // SuperLU's symmetric mode: diagonal pivots kept down to 0.001 of the column's largest
    SparseLU<SpMat, AMDOrdering<int>> s;
    s.isSymmetric(true);
    s.setPivotThreshold(0.001);
    return timeSolver<decltype(s)>(s, K, b, xStar, luFill<decltype(s)>);
  }
  if (name == "LDLT_AMD") {
    SimplicialLDLT<SpMat, Lower, AMDOrdering<int>> s;
    return timeSolver<decltype(s)>(s, K, b, xStar, ldltFill<decltype(s)>);
  }
  throw std::runtime_error("no such case");
}

//--------------------------------------------------------------------------
// collapseKff — Kt(fd,fd) of the collapse at refinement a, at the start of a load step
//--------------------------------------------------------------------------
// The calls of ample/ample.cpp's solve() up to the first detMPs (uvw = 0), after
// `after` load steps solved (solver=LDLT, NRitMax=20): after = 0 is load step 1 (the elastic
// tangent, every GIMP domain inside its cell: the sparsest pattern); after = 39 the
// state of the last step (domains across cell edges: more coupled nodes, plastic)
// Inputs:  a (h = 2 m / a) · mp (points per cell in each direction) · after
// Outputs: Kt(fd,fd) · nmp (number of points)
//--------------------------------------------------------------------------
SpMat collapseKff(int a, int mp, int after, long& nmp) {
  using namespace ample;
  const CliRequest req = parseArgs({"collapse", "a=" + std::to_string(a), "mp=" + std::to_string(mp),
                                    "solver=LDLT", "NRitMax=20"});  // a = 16 needs 11 passes in step 36
  Analysis an = req.setup->setupGrid(req.params);
  if (after > 0) {
    RunLog log;
    RunOptions opt;
    opt.quiet = true, opt.vtkEvery = 0, opt.lastStep = after;
    solveRun(an, log, opt);
  }
  nmp = long(an.mpData.size());
  const int nDoF = an.mesh.nDoF();
  elemMPinfo(an.mesh, an.mpData);
  const std::vector<int> fd = detFDoFsLone(an.mesh, an.mpData);
  DetMPsOut mps;
  mps.Kt = stiffnessPattern(nDoF, an.mpData);
  detMPs(Eigen::VectorXd::Zero(nDoF), an.mpData, an.formulation, mps);
  FreeSystem S;
  extractFreeSystem(mps.Kt, fd, S);
  return S.Kff;
}

struct Options {
  std::vector<int> a{2, 4, 8, 16, 32};
  int mp = 6, reps = 3, limit = 900, after = 0;
  double memGB = 12;
  std::vector<std::string> cases{"LU_COLAMD", "LU_AMD", "LU_AMD_T0.1", "LU_AMD_SYM", "LDLT_AMD"};
  std::string out = "docs/results/ordering.csv";
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> v;
  std::stringstream in(s);
  for (std::string w; std::getline(in, w, ',');) v.push_back(w);
  return v;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--a") { o.a.clear(); for (const auto& w : split(v)) o.a.push_back(std::stoi(w)); }
    else if (k == "--mp") o.mp = std::stoi(v);
    else if (k == "--reps") o.reps = std::stoi(v);
    else if (k == "--after") o.after = std::stoi(v);
    else if (k == "--limit") o.limit = std::stoi(v);
    else if (k == "--mem") o.memGB = std::stod(v);
    else if (k == "--cases") o.cases = split(v);
    else if (k == "--out") o.out = v;
    else { std::cerr << "solver_bench: unknown option " << k << "\n"; std::exit(2); }
  }
  return o;
}

//--------------------------------------------------------------------------
// forkedCase — runCase in a child: its own peak memory, a time and a memory limit
//--------------------------------------------------------------------------
// Inputs:  name · K, b, x* · limit (s) · memGB (address space of the child)
// Outputs: status ("ok", "time limit", "no memory", "failed: ...") · Timing · peak MB
//--------------------------------------------------------------------------
std::string forkedCase(const std::string& name, const SpMat& K, const Eigen::VectorXd& b,
                       const Eigen::VectorXd& xStar, const Options& o, Timing& t, double& peakMB) {
  int fds[2];
  if (pipe(fds) != 0) return "failed: pipe";
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    alarm(unsigned(o.limit));
    const rlim_t bytes = rlim_t(o.memGB * 1073741824.0);
    const rlimit lim{bytes, bytes};
    setrlimit(RLIMIT_AS, &lim);
    std::ostringstream s;
    s.precision(6);
    try {
      const Timing r = runCase(name, K, b, xStar);
      s << "ok " << r.analyse << " " << r.factorise << " " << r.solve << " " << r.fill << " " << r.error
        << " " << r.residual;
    } catch (const std::bad_alloc&) {
      s << "nomem";
    } catch (const std::exception& e) {
      s << "failed " << e.what();
    }
    const std::string msg = s.str();
    if (write(fds[1], msg.data(), msg.size()) < 0) _exit(4);
    _exit(0);
  }
  close(fds[1]);
  std::string msg;
  char buf[512];
  for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) msg.append(buf, size_t(n));
  close(fds[0]);
  int st = 0;
  rusage ru{};
  wait4(pid, &st, 0, &ru);
  peakMB = ru.ru_maxrss / 1024.0;
  if (WIFSIGNALED(st)) return WTERMSIG(st) == SIGALRM ? "time limit" : "killed by signal " + std::to_string(WTERMSIG(st));
  std::istringstream in(msg);
  std::string word;
  in >> word;
  if (word == "nomem") return "no memory";
  if (word != "ok") return "failed:" + msg.substr(std::min(msg.size(), size_t(6)));
  in >> t.analyse >> t.factorise >> t.solve >> t.fill >> t.error >> t.residual;
  return "ok";
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  std::ofstream csv(o.out);
  if (!csv) { std::cerr << "solver_bench: cannot write " << o.out << "\n"; return 1; }
  csv << "a,after_steps,nmp,nfd,nnz_K,solver,rep,status,analyse_s,factorise_s,solve_s,fill,factor_MB,peak_MB,base_MB,"
         "error,residual\n";
  for (int a : o.a) {
    long nmp = 0;
    const double t0 = now();
    const SpMat K = collapseKff(a, o.mp, o.after, nmp);  // the analysis is freed on return
    malloc_trim(0);
    const double build = now() - t0, base = residentMB();
    Eigen::VectorXd xStar(K.rows());
    for (int i = 0; i < K.rows(); ++i) xStar(i) = std::sin(i + 1.0);
    const Eigen::VectorXd b = K * xStar;
    std::printf("a = %d: %ld points, nfd = %ld, nnz = %ld (built in %.1f s, %.0f MB resident)\n", a, nmp,
                long(K.rows()), long(K.nonZeros()), build, base);
    for (const std::string& name : o.cases)
      for (int rep = 1; rep <= o.reps; ++rep) {
        Timing t;
        double peak = 0;
        const std::string status = forkedCase(name, K, b, xStar, o, t, peak);
        char line[512];
        std::snprintf(line, sizeof line, "%d,%d,%ld,%ld,%ld,%s,%d,%s,%.4g,%.4g,%.4g,%.0f,%.1f,%.0f,%.0f,%.2g,%.2g\n",
                      a, o.after, nmp, long(K.rows()), long(K.nonZeros()), name.c_str(), rep, status.c_str(),
                      t.analyse, t.factorise, t.solve, t.fill, t.fill * 12 / 1048576.0, peak, base, t.error,
                      t.residual);
        csv << line << std::flush;
        std::fputs(line, stdout);
        std::fflush(stdout);
        if (status != "ok") break;                                         // no repeats of a failure
        if (t.analyse + t.factorise + t.solve > 120) break;                 // one run of a slow case
      }
  }
  return 0;
}
