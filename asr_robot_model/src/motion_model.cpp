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

namespace {

/// `from` moved towards `to` by at most speed * seconds.
double approach(double from, double to, double speed, double seconds) {
  const double step = speed * std::max(seconds, 0.0);
  return std::abs(to - from) <= step ? to : from + std::copysign(step, to - from);
}

/// The base `seconds` into its turn-drive-turn; the yaw stays unwrapped within a turn.
void placeBase(const RobotState& from, const RobotState& to, const MotionSpeeds& speeds,
               double seconds, RobotState& state) {
  const double dx = to.x - from.x;
  const double dy = to.y - from.y;
  const double length = std::hypot(dx, dy);
  const double heading = length < kMinDrive ? to.yaw : std::atan2(dy, dx);
  const double first_turn = wrapAngle(heading - from.yaw);
  const double first_seconds = std::abs(first_turn) / speeds.turn_speed;
  if (seconds <= first_seconds) {
    state.yaw = wrapAngle(approach(from.yaw, from.yaw + first_turn, speeds.turn_speed, seconds));
    return;
  }
  seconds -= first_seconds;
  const double drive_seconds = length < kMinDrive ? 0.0 : length / speeds.base_speed;
  if (seconds <= drive_seconds) {
    const double fraction = seconds / drive_seconds;
    state.x = from.x + fraction * dx;
    state.y = from.y + fraction * dy;
    state.yaw = heading;
    return;
  }
  seconds -= drive_seconds;
  state.x = to.x;
  state.y = to.y;
  const double last_turn = wrapAngle(to.yaw - heading);
  state.yaw = std::abs(last_turn) <= speeds.turn_speed * seconds
                  ? to.yaw
                  : wrapAngle(approach(heading, heading + last_turn, speeds.turn_speed, seconds));
}

}  // namespace

RobotState stateAlong(const RobotState& from, const RobotState& to, const MotionSpeeds& speeds,
                      double seconds) {
  if (seconds >= motionBetween(from, to, speeds).seconds)
    return to;
  RobotState state = from;
  placeBase(from, to, speeds, seconds, state);
  state.pan = approach(from.pan, to.pan, speeds.pan_speed, seconds);
  state.tilt = approach(from.tilt, to.tilt, speeds.tilt_speed, seconds);
  return state;
}

}  // namespace asr_robot_model
