//--------------------------------------------------------------------------
// program — what `ample ARGS` does: read the command line, answer or run
//--------------------------------------------------------------------------
// program() is the whole of the program less its entry point: main.cpp (the
// command line) and wasm/ampleWasm.cpp (the same program in a browser tab,
// which hands on the run's state through stream) call it.
//   ample --list | --help | <setup> --help     the text on stdout
//   ample <setup> [name=value ...] [options]   the run (run.h: ample())
// Inputs:  args (the words after the program name) · stream (run.h; empty:
//          nothing handed on)
// Outputs: the exit status: 0 converged, 1 a load step did not converge or the
//          run could not go on, 2 bad input, 3 the student copy reached an
//          exercise not done; the message "ample: ..." on stderr
// Tests:   tests/test_cli.cpp, tests/wasm_compare.py (the browser build)
//--------------------------------------------------------------------------
#pragma once
#include "run.h"
#include <string>
#include <vector>

namespace ample {

int program(const std::vector<std::string>& args, const RunStream& stream = RunStream{});

}  // namespace ample
