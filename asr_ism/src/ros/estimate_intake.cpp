#include "asr_ism/ros/estimate_intake.hpp"

#include <geometry_msgs/PoseStamped.h>
#include <ros/console.h>
#include <tf2/exceptions.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include "asr_common/ros/object_estimate_message.hpp"
#include "asr_ism/common_types.hpp"

namespace asr_ism::ros_interface {

using namespace asr_common::ros_interface;

EstimateIntake::EstimateIntake(const tf2_ros::Buffer& buffer, std::string fixed_frame,
                               ros::Duration transform_timeout)
    : buffer_(buffer),
      fixed_frame_(std::move(fixed_frame)),
      transform_timeout_(transform_timeout) {}

std::optional<ObjectEstimate> EstimateIntake::accept(const asr_msgs::ObjectEstimate& message) {
  ObjectEstimate estimate;
  try {
    // Checked before the transform too, so that a NaN never reaches tf2.
    estimate = fromEstimateMessage(message);
  } catch (const InputError& error) {
    reject("invalid estimate", error.what());
    return std::nullopt;
  }
  const std::string& frame = message.header.frame_id;
  if (!frame.empty() && frame != fixed_frame_) {
    geometry_msgs::PoseStamped in;
    in.header = message.header;
    in.pose = message.pose.pose;
    try {
      // Without a timeout, the lookup that does not wait: tf2 logs an error for any lookup with
      // a timeout (even zero) on a buffer no listener thread fills, e.g. a bag's.
      const geometry_msgs::TransformStamped transform =
          transform_timeout_.isZero()
              ? buffer_.lookupTransform(fixed_frame_, frame, message.header.stamp)
              : buffer_.lookupTransform(fixed_frame_, frame, message.header.stamp,
                                        transform_timeout_);
      geometry_msgs::PoseStamped out;
      tf2::doTransform(in, out, transform);
      estimate.pose = fromPoseMessage(out.pose, describe(message) + " in " + fixed_frame_);
    } catch (const tf2::TransformException& error) {
      reject("no transform", describe(message) + ": " + error.what());
      return std::nullopt;
    } catch (const InputError& error) {
      reject("invalid estimate", error.what());
      return std::nullopt;
    }
  }
  ++accepted_;
  return estimate;
}

void EstimateIntake::reject(const std::string& reason, const std::string& detail) {
  ++rejected_;
  ++by_reason_[reason];
  ROS_WARN_THROTTLE(1.0, "rejected %s (%zu rejected so far)", detail.c_str(), rejected_);
}

}  // namespace asr_ism::ros_interface
