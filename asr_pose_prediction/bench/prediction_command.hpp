#pragma once

#include <string>
#include <vector>

namespace asr_pose_prediction::bench {

/// `asr_prediction_bench prediction [options]` (see main.cpp for the usage): measures, prints,
/// checks the targets; returns the exit code.
int runPredictionBenchmark(const std::vector<std::string>& arguments);

}  // namespace asr_pose_prediction::bench
