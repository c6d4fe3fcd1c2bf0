#pragma once

#include <string>
#include <vector>

namespace asr_ism_tree::bench {

/// `asr_bench topology [--json] [--out DIR] [--scenes A,B] [--recordings DIR] [--tests N]
/// [--alpha A] [--beta B] [--max-evaluations E] [--seed S] [--no-synthetic]`: relation topology
/// selection for the kitchen scenes, the paper's table beside ours, and the runtime figure.
int runTopologyCommand(const std::vector<std::string>& arguments);

}  // namespace asr_ism_tree::bench
