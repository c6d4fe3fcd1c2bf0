#pragma once

#include <Eigen/Geometry>

#include "asr_common/pose.hpp"
#include "asr_robot_model/robot_description.hpp"
#include "asr_robot_model/robot_state.hpp"

namespace asr_robot_model {

/// The pose of base_footprint in map for a state (the floor is z = 0).
Eigen::Isometry3d baseInMap(const RobotState& state);

/// The pose of camera_optical_frame in base_footprint for the head angles.
Eigen::Isometry3d cameraInBase(const RobotDescription& robot, double pan, double tilt);

/// Forward kinematics: the pose of camera_optical_frame in map for a state. Angles outside the
/// joint limits are computed all the same (checking them is the caller's business).
asr_common::Pose cameraPose(const RobotDescription& robot, const RobotState& state);

}  // namespace asr_robot_model
