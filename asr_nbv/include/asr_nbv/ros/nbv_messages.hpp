#pragma once

#include <asr_msgs/CameraFrustum.h>
#include <asr_msgs/CameraView.h>
#include <asr_msgs/PredictedPoseCloud.h>
#include <asr_msgs/ViewCosts.h>
#include <asr_msgs/VisitedView.h>

#include <vector>

#include "asr_nbv/nbv_documents.hpp"
#include "asr_nbv/next_best_view_planner.hpp"

// Conversions between next_best_view's messages and the planner's types.
namespace asr_nbv::ros_interface {

/// The clouds' poses as sent, unchecked: HypothesisSet rejects and counts the bad ones. Throws
/// asr_common::InputError naming the cloud if its frame is not `fixed_frame` (the node does
/// not transform) or an object has no type.
std::vector<PredictedCloud> fromCloudMessages(
    const std::vector<asr_msgs::PredictedPoseCloud>& clouds, const std::string& fixed_frame);

/// A view with its camera pose checked: throws asr_common::InputError naming `what` for a
/// non-finite pose or an unnormalised quaternion.
VisitedView fromVisitedViewMessage(const asr_msgs::VisitedView& message, const std::string& what);

asr_msgs::CameraFrustum toFrustumMessage(const asr_robot_model::Frustum& frustum);

asr_msgs::ViewCosts toCostsMessage(const InverseCosts& costs, double motion_seconds);

asr_msgs::CameraView toCameraViewMessage(const asr_common::Pose& camera,
                                         const asr_robot_model::RobotState& state,
                                         const std::vector<std::string>& types,
                                         const asr_robot_model::Frustum& frustum);

}  // namespace asr_nbv::ros_interface
