#pragma once

#include <asr_msgs/RobotState.h>

#include "asr_robot_model/robot_state.hpp"

// The robot state between the core and asr_msgs/RobotState, field by field (no checks: the
// driver's goal checks judge the values).
namespace asr_robot_model::ros_interface {

asr_msgs::RobotState toStateMessage(const RobotState& state);
RobotState fromStateMessage(const asr_msgs::RobotState& message);

}  // namespace asr_robot_model::ros_interface
