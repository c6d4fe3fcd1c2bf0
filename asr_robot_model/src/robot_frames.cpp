#include "asr_robot_model/robot_frames.hpp"

namespace asr_robot_model {

std::vector<FrameTransform> fixedFrames(const RobotDescription& robot) {
  std::vector<FrameTransform> frames;
  for (const UrdfJoint& joint : robot.joints) {
    if (!joint.moves)
      frames.push_back({joint.parent, joint.child, joint.origin});
  }
  return frames;
}

std::vector<FrameTransform> movingFrames(const RobotDescription& robot, double pan, double tilt) {
  std::vector<FrameTransform> frames;
  for (const UrdfJoint& joint : robot.joints) {
    if (!joint.moves)
      continue;
    const double angle = joint.name == robot.pan.name    ? pan
                         : joint.name == robot.tilt.name ? tilt
                                                         : 0.0;
    frames.push_back(
        {joint.parent, joint.child, joint.origin * Eigen::AngleAxisd(angle, joint.axis)});
  }
  return frames;
}

}  // namespace asr_robot_model
