#pragma once

#include <asr_msgs/PredictedPoseCloud.h>
#include <std_msgs/Header.h>

#include <vector>

#include "asr_pose_prediction/pose_predictor.hpp"

namespace asr_pose_prediction::ros_interface {

/// The predictions of PosePredictor::predict from `instances` (best first, as passed to it) as
/// one cloud per instance that contributed poses, best instance first, in the frame of `header`.
/// An instance that lacks nothing (or got no pose) has no cloud.
std::vector<asr_msgs::PredictedPoseCloud> toPoseCloudMessages(
    const std::vector<ObjectPrediction>& predictions, const std::vector<SceneInstance>& instances,
    const std_msgs::Header& header);

}  // namespace asr_pose_prediction::ros_interface
