// The subcommands of `asr robot`: forward and inverse kinematics and simulated detection.
#pragma once

#include <string>
#include <vector>

namespace asr_robot_model::tools {

int runFk(const std::vector<std::string>& arguments);
int runIk(const std::vector<std::string>& arguments);
int runDetect(const std::vector<std::string>& arguments);

}  // namespace asr_robot_model::tools
