// Test support: a tf transform message from a pose, for tests that feed tf buffers or bags.
#pragma once

#include <geometry_msgs/TransformStamped.h>
#include <ros/time.h>

#include <string>

#include "asr_common/pose.hpp"

namespace asr_common::testing {

/// `child` at `pose` in `parent`, stamped `stamp`.
inline geometry_msgs::TransformStamped transformMessage(const std::string& parent,
                                                        const std::string& child, const Pose& pose,
                                                        ros::Time stamp) {
  geometry_msgs::TransformStamped message;
  message.header.frame_id = parent;
  message.header.stamp = stamp;
  message.child_frame_id = child;
  message.transform.translation.x = pose.position.x();
  message.transform.translation.y = pose.position.y();
  message.transform.translation.z = pose.position.z();
  message.transform.rotation.x = pose.orientation.x();
  message.transform.rotation.y = pose.orientation.y();
  message.transform.rotation.z = pose.orientation.z();
  message.transform.rotation.w = pose.orientation.w();
  return message;
}

}  // namespace asr_common::testing
