//--------------------------------------------------------------------------
// writeOutput — the run's tables and summary
//--------------------------------------------------------------------------
// See writeOutput.h for the files and their columns.
//--------------------------------------------------------------------------
#include "writeOutput.h"
#include "ample/errors.h"
#include "plotting/makeVtk.h"
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>

namespace ample {

namespace fs = std::filesystem;

// the output folder (--out) made and writable, else bad input (exit 2) before any file is written
static void checkOutDir(const std::string& outDir) {
  std::error_code ec;
  fs::create_directories(outDir, ec);
  if (!ec && !fs::is_directory(outDir, ec)) ec = std::make_error_code(std::errc::not_a_directory);
  if (ec) throw InputError("--out " + outDir + ": cannot create the output folder (" + ec.message() + ")");
  const std::string probe = (fs::path(outDir) / ".ample_write_test").string();
  errno = 0;
  std::FILE* f = std::fopen(probe.c_str(), "w");
  if (!f)
    throw InputError("--out " + outDir + ": cannot write in the output folder (" +
                     std::strerror(errno) + ")");
  std::fclose(f);
  fs::remove(probe, ec);
}

void prepareOutput(const std::string& outDir) {
  checkOutDir(outDir);
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(outDir)) {
    const std::string n = e.path().filename().string();
    const bool ours = n == "mesh.vtk" || n == "steps.csv" || n == "residuals.csv" ||
                      n == "mp_final.csv" || n == "summary.json" || n == "history.csv" ||
                      ((n.rfind("mpData_", 0) == 0 || n.rfind("mesh_", 0) == 0) &&
                       e.path().extension() == ".vtk");
    if (ours) fs::remove(e.path(), ec);
  }
}

// a residual that went NaN or Inf is an empty field (CSV's missing number), never nan or a word
static std::string residualText(double fErr) {
  if (!std::isfinite(fErr)) return "";
  std::ostringstream s;
  s.precision(17);
  s << fErr;
  return s.str();
}

// JSON has no NaN or Inf: a number that is not finite is null (its reason written beside it)
static std::string jsonNumber(double v) {
  if (!std::isfinite(v)) return "null";
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

static std::string jsonString(const std::string& text) {
  std::string s = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') s += std::string("\\") + c;
    else if (c == '\n') s += "\\n";
    else if (c == '\t') s += "\\t";
    else if (static_cast<unsigned char>(c) < 0x20) s += ' ';
    else s += c;
  }
  return s + "\"";
}

// steps.csv: its header (pivots: with the negative_pivots column) and one row
static std::string stepsHeader(bool pivots) {
  return std::string("lstp,load_factor,NRit,fErr,converged,") + (pivots ? "negative_pivots," : "") + "seconds\n";
}

static std::string stepsRow(const StepRow& r, bool pivots) {
  std::ostringstream s;
  s.precision(17);
  s << r.lstp << "," << r.loadFactor << "," << r.NRit << "," << residualText(r.fErr) << ","
    << (r.converged ? 1 : 0) << ",";
  if (pivots) s << (r.negativePivots >= 0 ? std::to_string(r.negativePivots) : "") << ",";
  s << r.seconds << "\n";
  return s.str();
}

static bool hasPivots(const RunLog& log) {                              // solver=MUMPS's LDL^T
  return std::any_of(log.steps.begin(), log.steps.end(), [](const StepRow& r) { return r.negativePivots >= 0; });
}

static std::string stepsCsv(const RunLog& log) {
  const bool pivots = hasPivots(log);
  std::string s = stepsHeader(pivots);
  for (const StepRow& r : log.steps) s += stepsRow(r, pivots);
  return s;
}

static const char* residualsHeader = "lstp,NRit,fErr\n";

static std::string residualsRow(const ResidualRow& r) {
  return std::to_string(r.lstp) + "," + std::to_string(r.NRit) + "," + residualText(r.fErr) + "\n";
}

static std::string residualsCsv(const RunLog& log) {
  std::string s = residualsHeader;
  for (const ResidualRow& r : log.residuals) s += residualsRow(r);
  return s;
}

// history.csv: the header line of the columns of the first row, and one row (each line ends
// with "\n")
static std::string historyHeader(const std::vector<std::pair<std::string, double>>& row) {
  std::string s;
  for (size_t c = 0; c < row.size(); ++c) s += (c ? "," : "") + row[c].first;
  return s;
}

static std::string historyRow(const std::vector<std::pair<std::string, double>>& row) {
  std::ostringstream s;
  s.precision(17);
  for (size_t c = 0; c < row.size(); ++c) {  // a value that is not finite: empty
    const double v = row[c].second;
    s << (c ? "," : "");
    if (std::isfinite(v)) s << v;
  }
  return s.str();
}

static std::string historyCsv(const Analysis& an) {
  std::string s = historyHeader(an.history[0]) + "\n";
  for (const auto& row : an.history) s += historyRow(row) + "\n";
  return s;
}

// the text appended to a file, flushed to the operating system: a process killed after this
// returns leaves it in the file (the write of one step's rows is one fwrite)
static void appendText(const std::string& path, const std::string& text) {
  if (text.empty()) return;
  errno = 0;
  std::FILE* f = std::fopen(path.c_str(), "ab");
  bool ok = f && std::fwrite(text.data(), 1, text.size(), f) == text.size() && std::fflush(f) == 0;
  if (f) ok = std::fclose(f) == 0 && ok;
  if (!ok) throw RunError("cannot append to " + path + " (" + std::strerror(errno) + ")");
}

void startStepFiles(const std::string& outDir, const Analysis& an, RunLog& log) {
  log.stream = StepFiles{};
  log.stream.on = true;
  log.stream.pivots = an.solver == LinearSolver::MUMPS || an.solver == LinearSolver::PETSC;
  atomicWrite(outDir + "/steps.csv", stepsHeader(log.stream.pivots));
  atomicWrite(outDir + "/residuals.csv", residualsHeader);
}

void appendStepFiles(const std::string& outDir, const Analysis& an, RunLog& log) {
  StepFiles& w = log.stream;
  if (!w.on) return;
  std::string steps, residuals, history;
  for (; w.steps < log.steps.size(); ++w.steps) steps += stepsRow(log.steps[w.steps], w.pivots);
  for (; w.residuals < log.residuals.size(); ++w.residuals) residuals += residualsRow(log.residuals[w.residuals]);
  for (; w.history < an.history.size(); ++w.history)
    history += (w.history == 0 ? historyHeader(an.history[0]) + "\n" : std::string()) + historyRow(an.history[w.history]) + "\n";
  appendText(outDir + "/residuals.csv", residuals);                  // steps.csv last: a step
  appendText(outDir + "/history.csv", history);                      // there is whole in all three
  appendText(outDir + "/steps.csv", steps);
}

static std::string mpFinalCsv(const Analysis& an) {
  std::ostringstream s;
  s.precision(17);
  s << "X0,Y0,x,y,V0,V,sxx,syy,szz,sxy,syz,szx,lpx,lpy\n";
  for (const MaterialPoint& mp : an.mpData) {
    s << mp.X0(0) << "," << mp.X0(1) << "," << mp.mpC(0) << "," << mp.mpC(1) << "," << mp.vp0
      << "," << mp.vp;
    for (int c = 0; c < 6; ++c) s << "," << mp.sig(c);
    s << "," << mp.lp(0) << "," << mp.lp(1) << "\n";
  }
  return s.str();
}

// the setup's figures: a non-finite one is null, and "results_undefined" says why
static std::string resultsJson(const Results& res) {
  std::ostringstream s, why;
  s << "{";
  for (size_t i = 0; i < res.size(); ++i) {
    s << (i ? ", " : "") << jsonString(res[i].first) << ": " << jsonNumber(res[i].second);
    if (std::isfinite(res[i].second)) continue;
    std::string reason = "not finite (a division by zero or an overflow in the setup's measure)";
    for (const auto& w : res.why)
      if (w.first == res[i].first) reason = w.second;
    why << (why.tellp() > 0 ? ", " : "") << jsonString(res[i].first) << ": " << jsonString(reason);
  }
  s << "}";
  if (why.tellp() > 0) s << ",\n  \"results_undefined\": {" << why.str() << "}";
  return s.str();
}

// solver=MUMPS: the negative pivots of the last converged step's last LDL^T, and the first
// converged load step whose tangent had any (0: none); "" when no step had an LDL^T
static std::string negativePivotsJson(const RunLog& log) {
  int last = -1, from = 0;
  for (const StepRow& r : log.steps)
    if (r.converged && r.negativePivots >= 0) {
      last = r.negativePivots;
      if (from == 0 && r.negativePivots > 0) from = r.lstp;
    }
  if (last < 0) return "";
  return ",\n  \"negative_pivots\": " + std::to_string(last) + ",\n  \"negative_pivots_from\": " +
         std::to_string(from);
}

static std::string summaryJson(const Setup& setup, const Params& P, const Analysis& an,
                               const RunLog& log, const Results& res) {
  std::ostringstream s;
  s.precision(17);
  s << "{\n  \"setup\": " << jsonString(setup.name) << ",\n  \"parameters\": {";
  for (size_t i = 0; i < P.size(); ++i) s << (i ? ", " : "") << jsonString(P[i].name) << ": " << jsonNumber(P[i].value());
  s << "},\n  \"nmp\": " << an.mpData.size() << ",\n  \"nodes\": " << an.mesh.nodes()
    << ",\n  \"nDoF\": " << an.mesh.nDoF() << ",\n  \"lstps\": " << an.lstps
    << ",\n  \"total_NR_iterations\": " << log.totalNRit
    << ",\n  \"solver_analyses\": " << log.solverAnalyses << ",\n  \"lu_fallbacks\": " << log.luFallbacks
    << (an.split > 0 ? ",\n  \"splits\": " + std::to_string(log.splits) : std::string())
    << (an.loneFrom > 0 ? ",\n  \"lone_from\": " + std::to_string(an.loneFrom) : std::string())
    << (an.ghostFrom > 0 ? ",\n  \"ghost_from\": " + std::to_string(an.ghostFrom) : std::string())
    << negativePivotsJson(log)
    << ",\n  \"factorisations\": " << log.factorisations
    << ",\n  \"converged\": " << (log.converged ? "true" : "false")
    << ",\n  \"completed\": " << (log.converged ? "true" : "false")
    << ",\n  \"last_converged_step\": " << log.lastConverged
    << ",\n  \"message\": " << jsonString(log.message);
  const Timers& t = log.t;
  s << ",\n  \"wall_seconds\": " << t.total << ",\n  \"seconds\": {\"elemMPinfo\": "
    << t.elemMPinfo << ", \"detExtForce\": " << t.detExtForce << ", \"detFDoFs\": " << t.detFDoFs
    << ", \"detMPs\": " << t.detMPs << ", \"linSolve\": " << t.linSolve << ", \"updateMPs\": "
    << t.updateMPs << ", \"postPro\": " << t.postPro << "},\n  \"results\": " << resultsJson(res);
  for (const auto& r : res)
    if (r.first == "error") s << ",\n  \"error\": " << jsonNumber(r.second);
  s << "\n}\n";
  return s.str();
}

void writeOutput(const Setup& setup, const Params& P, const Analysis& an, const RunLog& log,
                 const std::string& outDir, bool quiet) {
  Results res;
  try {                    // a setup's figures of a state it cannot measure must not lose the files
    if (setup.results) res = setup.results(an, P);
  } catch (const RunError& e) {
    res = {{"results", NAN}};
    res.undefined("results", std::string("the setup's figures could not be computed: ") + e.what());
  }
  atomicWrite(outDir + "/steps.csv", stepsCsv(log));
  atomicWrite(outDir + "/residuals.csv", residualsCsv(log));
  atomicWrite(outDir + "/mp_final.csv", mpFinalCsv(an));
  if (!an.history.empty()) atomicWrite(outDir + "/history.csv", historyCsv(an));
  atomicWrite(outDir + "/summary.json", summaryJson(setup, P, an, log, res));
  if (quiet) return;
  std::printf("%s: %s after %d load steps, %d Newton-Raphson passes, %.3f s\n", setup.name,
              log.converged ? "converged" : "STOPPED", log.lastConverged, log.totalNRit, log.t.total);
  for (const auto& r : res) {
    std::string why = "not finite";
    for (const auto& w : res.why)
      if (w.first == r.first) why = w.second;
    if (std::isfinite(r.second)) std::printf("  %-14s %.10g\n", r.first.c_str(), r.second);
    else std::printf("  %-14s undefined: %s\n", r.first.c_str(), why.c_str());
  }
  std::printf("output in %s: draw it with plotting/plot_run.py %s (--animate: a page to play it)\n",
              outDir.c_str(), outDir.c_str());
}

}  // namespace ample
