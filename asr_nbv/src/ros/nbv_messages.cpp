#include "asr_nbv/ros/nbv_messages.hpp"

#include "asr_common/input_error.hpp"
#include "asr_common/ros/object_estimate_message.hpp"
#include "asr_robot_model/ros/robot_state_message.hpp"

namespace asr_nbv::ros_interface {

using asr_common::ros_interface::fromPoseMessage;
using asr_common::ros_interface::toPoseMessage;

std::vector<PredictedCloud> fromCloudMessages(
    const std::vector<asr_msgs::PredictedPoseCloud>& clouds, const std::string& fixed_frame) {
  std::vector<PredictedCloud> result;
  for (std::size_t c = 0; c < clouds.size(); ++c) {
    const asr_msgs::PredictedPoseCloud& cloud = clouds[c];
    const std::string name = "cloud " + std::to_string(c) + " (scene '" + cloud.scene + "')";
    if (cloud.header.frame_id != fixed_frame)
      throw asr_common::InputError(name + " is in frame '" + cloud.header.frame_id +
                                   "', not in the fixed frame '" + fixed_frame + "'");
    for (const asr_msgs::PredictedObjectPoses& object : cloud.objects) {
      if (object.type.empty())
        throw asr_common::InputError(name + ": an object has an empty type");
      PredictedCloud predicted;
      predicted.key = {object.type, object.instance_id};
      for (const geometry_msgs::Pose& pose : object.poses) {
        predicted.poses.emplace_back(
            Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z),
            Eigen::Quaterniond(pose.orientation.w, pose.orientation.x, pose.orientation.y,
                               pose.orientation.z));
      }
      result.push_back(std::move(predicted));
    }
  }
  return result;
}

VisitedView fromVisitedViewMessage(const asr_msgs::VisitedView& message, const std::string& what) {
  return {fromPoseMessage(message.camera, what + " camera"), message.types};
}

asr_msgs::CameraFrustum toFrustumMessage(const asr_robot_model::Frustum& frustum) {
  asr_msgs::CameraFrustum message;
  message.fovx = frustum.fovx();
  message.fovy = frustum.fovy();
  message.near = frustum.near();
  message.far = frustum.far();
  return message;
}

asr_msgs::ViewCosts toCostsMessage(const InverseCosts& costs, double motion_seconds) {
  asr_msgs::ViewCosts message;
  message.base = costs.base;
  message.rotation = costs.rotation;
  message.pan_tilt = costs.pan_tilt;
  message.recognition = costs.recognition;
  message.motion_seconds = motion_seconds;
  return message;
}

asr_msgs::CameraView toCameraViewMessage(const asr_common::Pose& camera,
                                         const asr_robot_model::RobotState& state,
                                         const std::vector<std::string>& types,
                                         const asr_robot_model::Frustum& frustum) {
  asr_msgs::CameraView message;
  message.camera = toPoseMessage(camera);
  message.state = asr_robot_model::ros_interface::toStateMessage(state);
  message.types = types;
  message.frustum = toFrustumMessage(frustum);
  return message;
}

}  // namespace asr_nbv::ros_interface
