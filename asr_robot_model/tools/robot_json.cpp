#include "robot_json.hpp"

#include <vector>

namespace asr_robot_model::tools {

nlohmann::json poseJson(const asr_common::Pose& pose) {
  return {
      {"position", {{"x", pose.position.x()}, {"y", pose.position.y()}, {"z", pose.position.z()}}},
      {"orientation",
       {{"x", pose.orientation.x()},
        {"y", pose.orientation.y()},
        {"z", pose.orientation.z()},
        {"w", pose.orientation.w()}}}};
}

nlohmann::json stateJson(const RobotState& state) {
  return {
      {"x", state.x}, {"y", state.y}, {"yaw", state.yaw}, {"pan", state.pan}, {"tilt", state.tilt}};
}

RobotState stateOption(const asr_common::cli::CommandLine& options, const std::string& name,
                       const RobotState& fallback) {
  if (!options.has(name))
    return fallback;
  const std::vector<double> v = options.numbers(name, 5, "x y yaw pan tilt");
  return {v[0], v[1], v[2], v[3], v[4]};
}

void poseOption(const asr_common::cli::CommandLine& options, const std::string& name,
                Eigen::Vector3d& position, Eigen::Quaterniond& orientation) {
  const std::vector<double> v = options.numbers(name, 7, "x y z qx qy qz qw");
  position = {v[0], v[1], v[2]};
  orientation = Eigen::Quaterniond(v[6], v[3], v[4], v[5]);
}

}  // namespace asr_robot_model::tools
