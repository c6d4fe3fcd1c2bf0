#pragma once

#include <string>
#include <vector>

namespace asr_ism_tree::bench {

/// `asr_bench recognition [--json] [--recordings DIR] [--threads N] [--no-synthetic]
/// [--synthetic-json FILE]`: benchmarks learning and recognition on the kitchen scenes and on
/// synthetic demonstrations. Returns the exit code.
int runRecognitionCommand(const std::vector<std::string>& arguments);

}  // namespace asr_ism_tree::bench
