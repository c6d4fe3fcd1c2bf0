#include "asr_common/ros/object_estimate_message.hpp"

#include "asr_common/input_error.hpp"

namespace asr_common::ros_interface {

geometry_msgs::Pose toPoseMessage(const Pose& pose) {
  geometry_msgs::Pose message;
  message.position.x = pose.position.x();
  message.position.y = pose.position.y();
  message.position.z = pose.position.z();
  message.orientation.x = pose.orientation.x();
  message.orientation.y = pose.orientation.y();
  message.orientation.z = pose.orientation.z();
  message.orientation.w = pose.orientation.w();
  return message;
}

Pose fromPoseMessage(const geometry_msgs::Pose& message, const std::string& what) {
  return validatedPose(Eigen::Vector3d(message.position.x, message.position.y, message.position.z),
                       Eigen::Quaterniond(message.orientation.w, message.orientation.x,
                                          message.orientation.y, message.orientation.z),
                       what);
}

std::string describe(const asr_msgs::ObjectEstimate& message) {
  const ObjectKey key{message.type, message.instance_id};
  return "object estimate " + (message.type.empty() ? std::string("(no type)") : key.toString()) +
         " in frame '" + message.header.frame_id + "'";
}

ObjectEstimate fromEstimateMessage(const asr_msgs::ObjectEstimate& message) {
  if (message.type.empty())
    throw InputError(describe(message) + ": the type is empty");
  return {{message.type, message.instance_id},
          fromPoseMessage(message.pose.pose, describe(message))};
}

asr_msgs::ObjectEstimate toEstimateMessage(const ObjectEstimate& estimate,
                                           const std_msgs::Header& header) {
  asr_msgs::ObjectEstimate message;
  message.header = header;
  message.type = estimate.key.type;
  message.instance_id = estimate.key.id;
  message.pose.pose = toPoseMessage(estimate.pose);
  return message;
}

}  // namespace asr_common::ros_interface
