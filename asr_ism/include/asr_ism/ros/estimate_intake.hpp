#pragma once

#include <asr_msgs/ObjectEstimate.h>
#include <ros/duration.h>
#include <tf2_ros/buffer.h>

#include <map>
#include <optional>
#include <string>

#include "asr_ism/common_types.hpp"

namespace asr_ism::ros_interface {

/// Where object estimates enter a node, from topics and service requests alike: each is checked,
/// transformed into the fixed frame with tf2 and converted. A rejected estimate (empty type,
/// NaN, zero or unnormalised quaternion, no transform) is counted by reason and reported with a
/// throttled warning; the node keeps running. An empty frame_id means the fixed frame.
class EstimateIntake {
 public:
  /// `buffer` must outlive the intake; `transform_timeout` is how long to wait for tf data.
  EstimateIntake(const tf2_ros::Buffer& buffer, std::string fixed_frame,
                 ros::Duration transform_timeout = ros::Duration(0.1));

  /// The estimate in the fixed frame, or nothing if it was rejected.
  std::optional<ObjectEstimate> accept(const asr_msgs::ObjectEstimate& message);

  const std::string& fixedFrame() const { return fixed_frame_; }
  std::size_t acceptedCount() const { return accepted_; }
  std::size_t rejectedCount() const { return rejected_; }
  /// Rejections per reason ("invalid estimate", "no transform").
  const std::map<std::string, std::size_t>& rejectedByReason() const { return by_reason_; }

 private:
  void reject(const std::string& reason, const std::string& detail);

  const tf2_ros::Buffer& buffer_;
  std::string fixed_frame_;
  ros::Duration transform_timeout_;
  std::size_t accepted_ = 0;
  std::size_t rejected_ = 0;
  std::map<std::string, std::size_t> by_reason_;
};

}  // namespace asr_ism::ros_interface
