#pragma once

#include <asr_msgs/ObjectEstimate.h>
#include <geometry_msgs/Pose.h>
#include <std_msgs/Header.h>

#include "asr_common/object.hpp"

// Conversions between the suite's messages and the ROS-free core's types. Everything a node
// receives goes through the checked conversions, so the core never sees a NaN or a zero
// quaternion from the wire.
namespace asr_common::ros_interface {

/// A pose the suite computed, as a message (no checks needed).
geometry_msgs::Pose toPoseMessage(const Pose& pose);

/// A pose from a message, checked like any user input: throws InputError naming `what` for
/// non-finite values or a zero or unnormalised (beyond 1e-3) quaternion.
Pose fromPoseMessage(const geometry_msgs::Pose& message, const std::string& what);

/// An estimate from a detector, checked: throws InputError naming the estimate (type, id and
/// frame) for an empty type or a bad pose. The frame is not looked at; see EstimateIntake.
ObjectEstimate fromEstimateMessage(const asr_msgs::ObjectEstimate& message);

/// An estimate as a message in the frame and at the time of `header`; zero covariance.
asr_msgs::ObjectEstimate toEstimateMessage(const ObjectEstimate& estimate,
                                           const std_msgs::Header& header);

/// "type:id in frame 'f'" for messages about an estimate.
std::string describe(const asr_msgs::ObjectEstimate& message);

}  // namespace asr_common::ros_interface
