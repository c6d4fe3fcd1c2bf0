// JSON of the robot tools: poses and states as `asr robot ... --json` prints them.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "asr_common/cli/command_line.hpp"
#include "asr_common/pose.hpp"
#include "asr_robot_model/robot_state.hpp"

namespace asr_robot_model::tools {

/// {"position": {x, y, z}, "orientation": {x, y, z, w}}
nlohmann::json poseJson(const asr_common::Pose& pose);
/// {"x", "y", "yaw", "pan", "tilt"}
nlohmann::json stateJson(const RobotState& state);

/// The state of option `name` ("x y yaw pan tilt"), `fallback` if it is not given. Throws
/// UsageError naming the option unless it is five finite numbers.
RobotState stateOption(const asr_common::cli::CommandLine& options, const std::string& name,
                       const RobotState& fallback);
/// The pose of option `name` ("x y z qx qy qz qw"); the quaternion is checked by the caller.
void poseOption(const asr_common::cli::CommandLine& options, const std::string& name,
                Eigen::Vector3d& position, Eigen::Quaterniond& orientation);

}  // namespace asr_robot_model::tools
