#include "asr_robot_model/motion_model.hpp"

#include <algorithm>
#include <cmath>

#include "asr_common/input_error.hpp"

namespace asr_robot_model {

MotionSpeeds speedsOf(const RobotDescription& robot) {
  MotionSpeeds speeds;
  speeds.pan_speed = robot.pan.velocity;
  speeds.tilt_speed = robot.tilt.velocity;
  return speeds;
}

void checkSpeeds(const MotionSpeeds& speeds) {
  const std::pair<const char*, double> fields[] = {{"base_speed", speeds.base_speed},
                                                   {"turn_speed", speeds.turn_speed},
                                                   {"pan_speed", speeds.pan_speed},
                                                   {"tilt_speed", speeds.tilt_speed}};
  for (const auto& [name, value] : fields) {
    if (!(std::isfinite(value) && value > 0.0))
      throw asr_common::InputError(std::string("motion speeds: ") + name +
                                   " must be a positive number");
  }
}

Motion motionBetween(const RobotState& from, const RobotState& to, const MotionSpeeds& speeds) {
  Motion motion;
  const double dx = to.x - from.x;
  const double dy = to.y - from.y;
  motion.path_length = std::hypot(dx, dy);
  if (motion.path_length < kMinDrive) {
    motion.path_length = 0.0;
    motion.turning = std::abs(wrapAngle(to.yaw - from.yaw));
  } else {
    const double heading = std::atan2(dy, dx);
    motion.turning =
        std::abs(wrapAngle(heading - from.yaw)) + std::abs(wrapAngle(to.yaw - heading));
  }
  motion.base_seconds = motion.turning / speeds.turn_speed + motion.path_length / speeds.base_speed;
  motion.head_seconds = std::max(std::abs(to.pan - from.pan) / speeds.pan_speed,
                                 std::abs(to.tilt - from.tilt) / speeds.tilt_speed);
  motion.seconds = std::max(motion.base_seconds, motion.head_seconds);
  return motion;
}

}  // namespace asr_robot_model
