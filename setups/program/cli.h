//--------------------------------------------------------------------------
// cli — the command line: which setup, its parameters, output options
//--------------------------------------------------------------------------
//   ample --list | --help
//   ample <setup> --help
//   ample <setup> [name=value ...] [--out DIR] [--vtk N] [--vtk-format ascii|binary]
//                 [--accept-floor] [--quiet]
// Every value is checked before any work: a plain decimal number (no hex, inf,
// nan or spaces), written as a whole number (digits, optional sign) where one is
// required, or a choice's name in any case; inside the parameter's range. Unknown
// names and options, a name or option given twice, an option's missing value and
// words after --list, --help or <setup> --help are refused.
// Inputs:  args (the words after the program name)
// Outputs: CliRequest; throws InputError naming the parameter, the value
//          given and what is allowed (the program then exits with status 2)
// Tests:   tests/test_cli.cpp
//--------------------------------------------------------------------------
#pragma once
#include "setups/program/run.h"
#include <string>
#include <vector>

namespace ample {

enum class CliMode { List, Help, SetupHelp, Run };

struct CliRequest {
  CliMode mode = CliMode::Help;
  const Setup* setup = nullptr;
  Params params;        // the setup's parameters (its struct) with the command line applied
  RunOptions options;
};

CliRequest parseArgs(const std::vector<std::string>& args);
std::string usageText();
std::string listText();
std::string setupHelpText(const Setup& setup);

}  // namespace ample
