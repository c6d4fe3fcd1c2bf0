#include "asr_robot_model/forward_kinematics.hpp"

namespace asr_robot_model {

Eigen::Isometry3d baseInMap(const RobotState& state) {
  Eigen::Isometry3d base = Eigen::Isometry3d::Identity();
  base.translation() = Eigen::Vector3d(state.x, state.y, 0.0);
  base.linear() = Eigen::AngleAxisd(state.yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return base;
}

Eigen::Isometry3d cameraInBase(const RobotDescription& robot, double pan, double tilt) {
  return robot.base_to_pan * Eigen::AngleAxisd(pan, robot.pan.axis) * robot.pan_to_tilt *
         Eigen::AngleAxisd(tilt, robot.tilt.axis) * robot.tilt_to_camera;
}

asr_common::Pose cameraPose(const RobotDescription& robot, const RobotState& state) {
  const Eigen::Isometry3d camera = baseInMap(state) * cameraInBase(robot, state.pan, state.tilt);
  return asr_common::Pose(camera.translation(), Eigen::Quaterniond(camera.linear()));
}

}  // namespace asr_robot_model
