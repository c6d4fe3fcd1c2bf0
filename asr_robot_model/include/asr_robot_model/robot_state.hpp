#pragma once

#include <string>

namespace asr_robot_model {

/// Where the robot is: base pose on the floor of `map` (x, y in metres, yaw in radians about the
/// vertical) and the pan and tilt angles of the head in radians.
struct RobotState {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;
  double pan = 0.0;
  double tilt = 0.0;
};

/// Angle wrapped into (-pi, pi].
double wrapAngle(double angle);

/// Throws asr_common::InputError naming `what` and the field if a value is not finite.
void checkFinite(const RobotState& state, const std::string& what);

}  // namespace asr_robot_model
