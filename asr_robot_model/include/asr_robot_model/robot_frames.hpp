#pragma once

#include <Eigen/Geometry>

#include <string>
#include <vector>

#include "asr_robot_model/robot_description.hpp"

namespace asr_robot_model {

/// The pose of frame `child` in frame `parent`.
struct FrameTransform {
  std::string parent;
  std::string child;
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
};

/// The transforms of the URDF's joints that never move (published once, latched).
std::vector<FrameTransform> fixedFrames(const RobotDescription& robot);

/// The transforms of the URDF's moving joints for the head angles: the pan and tilt joints at
/// `pan` and `tilt`, any other moving joint (a wheel, say) at zero.
std::vector<FrameTransform> movingFrames(const RobotDescription& robot, double pan, double tilt);

}  // namespace asr_robot_model
