#include "asr_robot_model/ros/robot_state_message.hpp"

namespace asr_robot_model::ros_interface {

asr_msgs::RobotState toStateMessage(const RobotState& state) {
  asr_msgs::RobotState message;
  message.x = state.x;
  message.y = state.y;
  message.yaw = state.yaw;
  message.pan = state.pan;
  message.tilt = state.tilt;
  return message;
}

RobotState fromStateMessage(const asr_msgs::RobotState& message) {
  return {message.x, message.y, message.yaw, message.pan, message.tilt};
}

}  // namespace asr_robot_model::ros_interface
