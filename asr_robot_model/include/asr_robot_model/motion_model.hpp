#pragma once

#include "asr_robot_model/robot_description.hpp"
#include "asr_robot_model/robot_state.hpp"

namespace asr_robot_model {

/// Top speeds: base in m/s and rad/s, head joints in rad/s.
struct MotionSpeeds {
  double base_speed = 0.5;
  double turn_speed = 0.8;
  double pan_speed = 1.0;
  double tilt_speed = 1.0;
};

/// The default base speeds with the head speeds of the URDF's joint velocities.
MotionSpeeds speedsOf(const RobotDescription& robot);

/// Throws asr_common::InputError naming the field if a speed is not a positive finite number.
void checkSpeeds(const MotionSpeeds& speeds);

/// How the robot goes from one state to another: the base turns on the spot towards the goal,
/// drives straight (forwards), turns into the goal's yaw; pan and tilt move at the same time,
/// each at its own speed. The slower of base and head sets the duration.
struct Motion {
  double seconds = 0.0;       // max(base_seconds, head_seconds)
  double base_seconds = 0.0;  // turning / turn_speed + path_length / base_speed
  double head_seconds = 0.0;  // max(|pan change| / pan_speed, |tilt change| / tilt_speed)
  double path_length = 0.0;   // metres driven
  double turning = 0.0;       // radians turned on the spot, both turns together
};

/// Base moves shorter than this are a turn on the spot (no heading towards the goal).
inline constexpr double kMinDrive = 1e-6;

/// The motion from `from` to `to` (both already within the joint limits; yaws are compared
/// modulo 2 pi, each turn the short way round).
Motion motionBetween(const RobotState& from, const RobotState& to, const MotionSpeeds& speeds);

/// Where the robot is `seconds` into the motion from `from` to `to` (the motion motionBetween
/// times): the base in its first turn, its drive or its last turn, each joint of the head moving
/// at its speed until it arrives. Before 0 it is `from`, from the motion's end on it is `to`.
RobotState stateAlong(const RobotState& from, const RobotState& to, const MotionSpeeds& speeds,
                      double seconds);

}  // namespace asr_robot_model
