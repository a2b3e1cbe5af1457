//--------------------------------------------------------------------------
// ampleWasm — the program in a browser tab: its entry points for JavaScript
//--------------------------------------------------------------------------
// The program built with emscripten (the preset wasm: build/wasm/ample_wasm.js
// and .wasm) has no main(); the page's worker (plotting/viewer/worker.js) and
// tests/wasm_run.js call these functions, each with the command line's words
// joined by "\n" (e.g. "collapse\na=4\nmp=4\n--out\n/out"):
//   ampleSetups()     the table of setups and their parameters (setups.h:
//                     names, defaults, ranges, whole numbers, choice names,
//                     help), as JSON: the page builds its form from it
//   ampleCheck(args)  "" if the command line's checks (cli.h: parseArgs)
//                     pass, else their message: the form shows it as is
//   ampleSetup(args)  the set-up state of the run args asks for (setupGrid),
//                     handed on as frame 0: the page's first picture
//   ampleRun(args)    program(args) (program.h): the run, its files in the
//                     module's memory file system, its exit status; the state
//                     is handed on as it goes (run.h: RunStream)
// What is handed on goes to the module's callbacks (JavaScript, set before the
// call; none set: nothing is sent):
//   Module.onGrid(nodes Float64Array [x0 y0 x1 ...], cells Int32Array, nen)
//       the background mesh, at the start, and after each step where it moves
//   Module.onPass(lstp, NRit, fErr)      each Newton-Raphson pass (eq 35's fErr)
//   Module.onFrame(lstp, loadFactor, NRit, fErr, nmp, Float64Array)
//       the points after each converged load step (lstp 0: as set up), column
//       after column (frameColumns: nmp values each)
// Fields: positions x, y; displacement ux, uy; Cauchy stress sxx, syy, szz,
// sxy; rho = sqrt(2 J2) (as rho_vonMises of the VTK files); the plastic strain
// epsP = sqrt(2/3 e:e), e = 1/2 ln(F F^T) - epsE ([AMPLE] eqs 9-10: the total
// log strain less the elastic one; NaN for formulation=SS, which keeps no total
// strain); volume V; domain half lengths lpx, lpy.
// Tests:   tests/wasm_compare.py (node against the native program),
//          tests/viewer_test.py (the page in headless Chromium)
//--------------------------------------------------------------------------
#include "ample/errors.h"
#include "ample/stiffness/tensorOps.h"
#include "ample/solver/solverChoice.h"
#include "setups/program/cli.h"
#include "setups/program/program.h"
#include <emscripten.h>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

// the JavaScript side of the stream: copies out of the module's memory, then the callback
EM_JS(void, jsGrid, (const double* nodes, int nn, const int* cells, int nels, int nen), {
  if (!Module.onGrid) return;
  Module.onGrid(HEAPF64.slice(nodes >> 3, (nodes >> 3) + 2 * nn),
                HEAP32.slice(cells >> 2, (cells >> 2) + nels * nen), nen);
});
EM_JS(void, jsPass, (int lstp, int NRit, double fErr), {
  if (Module.onPass) Module.onPass(lstp, NRit, fErr);
});
EM_JS(void, jsFrame, (int lstp, double loadFactor, int NRit, double fErr, int nmp, const double* v, int count), {
  if (Module.onFrame) Module.onFrame(lstp, loadFactor, NRit, fErr, nmp, HEAPF64.slice(v >> 3, (v >> 3) + count));
});

namespace ample {

// the columns of a frame, in order (the page reads them by these names)
static const char* frameColumns[] = {"x", "y", "ux", "uy", "sxx", "syy", "szz", "sxy",
                                     "vonMises", "epsP", "V", "lpx", "lpy"};
static const int nColumns = int(sizeof frameColumns / sizeof frameColumns[0]);

// the words of a command line joined by "\n"
static std::vector<std::string> wordsOf(const char* text) {
  std::vector<std::string> words;
  std::istringstream s(text ? text : "");
  for (std::string w; std::getline(s, w, '\n');) words.push_back(w);
  return words;
}

// rho = sqrt(2 J2) of a Cauchy stress (Voigt order, tensor shear)
static double vonMises(const Vector6d& sig) {
  const double p = sig.head<3>().sum() / 3.0;
  return std::sqrt((sig.head<3>().array() - p).square().sum() + 2 * sig.tail<3>().squaredNorm());
}

// epsP = sqrt(2/3 e:e), e = 1/2 ln(F F^T) - epsE: the log strain that is not elastic
static double plasticStrain(const MaterialPoint& mp, Formulation form) {
  if (form == Formulation::SS) return NAN;                  // no total strain kept
  const Matrix3d e = 0.5 * symLog(mp.F * mp.F.transpose()) - strainToTensor(mp.epsE);
  return std::sqrt(2.0 / 3.0 * e.squaredNorm());
}

// the mesh to the page: nodal coordinates and each cell's nodes
static void sendGrid(const Mesh& mesh) {
  std::vector<double> nodes(mesh.coord.data(), mesh.coord.data() + mesh.coord.size());
  std::vector<int> cells(mesh.etpl.data(), mesh.etpl.data() + mesh.etpl.size());
  jsGrid(nodes.data(), int(mesh.coord.rows()), cells.data(), int(mesh.etpl.rows()), int(mesh.etpl.cols()));
}

// the points to the page, one column (frameColumns) after the other
static void sendFrame(const Analysis& an, int lstp, double loadFactor, int NRit, double fErr) {
  const std::vector<MaterialPoint>& mpData = an.mpData;
  const size_t n = mpData.size();
  std::vector<double> v(nColumns * n);
  for (size_t p = 0; p < n; ++p) {
    const MaterialPoint& mp = mpData[p];
    const double row[] = {mp.mpC(0), mp.mpC(1), mp.u(0), mp.u(1), mp.sig(0), mp.sig(1), mp.sig(2), mp.sig(3),
                          vonMises(mp.sig), plasticStrain(mp, an.formulation), mp.vp, mp.lp(0), mp.lp(1)};
    for (int c = 0; c < nColumns; ++c) v[c * n + p] = row[c];
  }
  jsFrame(lstp, loadFactor, NRit, fErr, int(n), v.data(), int(v.size()));
}

// the stream of the page: the set-up state, every pass, every converged step
static RunStream pageStream() {
  RunStream s;
  s.start = [](const Analysis& an) {
    sendGrid(an.mesh);
    sendFrame(an, 0, 0.0, 0, NAN);
  };
  s.pass = [](int lstp, int NRit, double fErr) { jsPass(lstp, NRit, fErr); };
  s.step = [](const Analysis& an, const RunLog& log, int lstp) {
    if (an.fem || an.gridMoves) sendGrid(an.mesh);
    const StepRow& r = log.steps.back();                     // the converged attempt's row
    sendFrame(an, lstp, r.loadFactor, r.NRit, r.fErr);
  };
  return s;
}

static std::string jsonString(const std::string& text) {
  std::string s = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') s += std::string("\\") + c;
    else if (c == '\n') s += "\\n";
    else if (static_cast<unsigned char>(c) < 0x20) s += ' ';
    else s += c;
  }
  return s + "\"";
}

static std::string jsonNumber(double v) {
  if (!std::isfinite(v)) return "null";                     // an open end: -inf or inf
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// one parameter of the table, as the page's form needs it
static std::string paramJson(const Param& p) {
  std::ostringstream s;
  s << "{\"name\": " << jsonString(p.name) << ", \"value\": " << jsonNumber(p.value())
    << ", \"lo\": " << jsonNumber(p.lo) << ", \"hi\": " << jsonNumber(p.hi)
    << ", \"loOpen\": " << (p.loOpen ? "true" : "false") << ", \"hiOpen\": " << (p.hiOpen ? "true" : "false")
    << ", \"integer\": " << (p.isInteger ? "true" : "false") << ", \"names\": [";
  for (size_t k = 0; k < p.names.size(); ++k) s << (k ? ", " : "") << jsonString(p.names[k]);
  s << "], \"range\": " << jsonString(rangeText(p)) << ", \"help\": " << jsonString(p.helpText) << "}";
  return s.str();
}

static std::string setupsJson() {
  std::ostringstream s;
  s << "{\"solvers\": " << jsonString(solversBuilt()) << ", \"usage\": " << jsonString(usageText())
    << ", \"columns\": [";
  for (int c = 0; c < nColumns; ++c) s << (c ? ", " : "") << jsonString(frameColumns[c]);
  s << "], \"setups\": [";
  bool first = true;
  for (const Setup& st : setupsTable()) {
    s << (first ? "" : ",") << "\n {\"name\": " << jsonString(st.name) << ", \"description\": "
      << jsonString(st.description) << ", \"params\": [";
    first = false;
    const Params P = st.params();
    for (size_t i = 0; i < P.size(); ++i) s << (i ? ",\n  " : "\n  ") << paramJson(P[i]);
    s << "]}";
  }
  s << "]}\n";
  return s.str();
}

}  // namespace ample

extern "C" {

EMSCRIPTEN_KEEPALIVE const char* ampleSetups() {
  static const std::string text = ample::setupsJson();
  return text.c_str();
}

EMSCRIPTEN_KEEPALIVE const char* ampleCheck(const char* args) {
  static std::string message;
  message.clear();
  try {
    ample::parseArgs(ample::wordsOf(args));
  } catch (const ample::InputError& e) {
    message = e.what();
  }
  return message.c_str();
}

EMSCRIPTEN_KEEPALIVE int ampleSetup(const char* args) {
  using namespace ample;
  try {
    const CliRequest req = parseArgs(wordsOf(args));
    if (req.mode != CliMode::Run) return 2;
    const Analysis an = req.setup->setupGrid(req.params);
    pageStream().start(an);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "ample: " << e.what() << "\n";
    return 2;
  }
}

EMSCRIPTEN_KEEPALIVE int ampleRun(const char* args) {
  return ample::program(ample::wordsOf(args), ample::pageStream());
}

}  // extern "C"
