#pragma once

#include <string>
#include <vector>

namespace asr_pose_prediction::tools {

/// `asr ism predict`: parses its options, recognises, predicts, prints; returns the exit code.
int runPredict(const std::vector<std::string>& arguments);

}  // namespace asr_pose_prediction::tools
