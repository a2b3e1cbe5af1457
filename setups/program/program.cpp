//--------------------------------------------------------------------------
// program — what `ample ARGS` does: read the command line, answer or run
//--------------------------------------------------------------------------
// See program.h for inputs and outputs; main() (main.cpp) and the browser
// tab's ampleRun (wasm/ampleWasm.cpp) call it.
//--------------------------------------------------------------------------
#include "program.h"
#include "ample/errors.h"
#include "cli.h"
#include <iostream>

namespace ample {

int program(const std::vector<std::string>& args, const RunStream& stream) {
  CliRequest req;
  try {
    req = parseArgs(args);
  } catch (const InputError& e) {
    std::cerr << "ample: " << e.what() << "\n";
    return 2;
  }
  switch (req.mode) {
    case CliMode::List: std::cout << listText(); return 0;
    case CliMode::Help: std::cout << usageText() << "setups:\n" << listText(); return 0;
    case CliMode::SetupHelp: std::cout << setupHelpText(*req.setup); return 0;
    case CliMode::Run: break;
  }
  req.options.stream = stream;
  try {
    return ample(*req.setup, req.params, req.options);
  } catch (const ExerciseNotDone& e) {  // the student copy (docs/exercises.md)
    std::cerr << "ample: needs exercise " << e.what() << "\n";
    return 3;
  } catch (const InputError& e) {      // the setup's problem is inconsistent, or --out
    std::cerr << "ample: " << e.what() << "\n";   // cannot be made (before any file is written)
    return 2;
  } catch (const std::exception& e) {  // e.g. a result file cannot be written at the end
    std::cerr << "ample: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace ample
