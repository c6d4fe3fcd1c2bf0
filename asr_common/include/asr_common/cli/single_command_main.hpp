// The main() of a tool with a single command, shared by ism_predict and asr_prediction_bench.
#pragma once

#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "asr_common/cli/command_main.hpp"

namespace asr_common::cli {

/// Runs `command` as the only command of `program` through the suite's runCommandMain, so errors
/// read "program command: ..." with its exit codes (1 bad input, 2 bad command line). The
/// command's name may be given as the first argument or left out (the asr script leaves it
/// out); --help or -h anywhere prints the usage.
inline int runSingleCommandMain(const std::string& program, const std::string& command,
                                const std::string& usage, asr_common::cli::Command run, int argc,
                                char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
      std::cout << usage;
      return 0;
    }
  }
  std::vector<char*> arguments(argv, argv + argc);
  std::string name = command;
  if (argc < 2 || command != argv[1])
    arguments.insert(arguments.begin() + 1, name.data());
  return asr_common::cli::runCommandMain(program, usage, {{command, run}},
                                         static_cast<int>(arguments.size()), arguments.data());
}

}  // namespace asr_common::cli
