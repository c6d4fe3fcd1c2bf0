#pragma once

#include <cstdint>
#include <vector>

#include "asr_common/object.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"
#include "asr_pose_prediction/pose_predictor.hpp"

namespace asr_pose_prediction {

/// How close a cloud of predicted poses comes to the true pose of an object.
struct NearestPoseError {
  /// Distance from the true position to the nearest predicted position, metres.
  double distance = 0.0;
  /// Angle between the true orientation and that of the pose nearest in position, radians.
  double angle_at_nearest = 0.0;
  /// Smallest angle between the true orientation and any predicted orientation, radians.
  double smallest_angle = 0.0;
};

/// Throws InputError for an empty cloud.
NearestPoseError nearestPoseError(const Pose& truth, const std::vector<Pose>& predictions);

/// The outcome of predicting one object left out of a configuration.
struct LeftOutPrediction {
  bool instance_found = false;
  /// Of the best instance of the rest; 0 if none was found.
  double confidence = 0.0;
  NearestPoseError error;  // meaningful only if instance_found
};

/// Leaves estimate `left_out` out of `configuration`, recognises the rest with `recognizer`, and
/// predicts `samples` poses of the left-out object from the best instance (seed `seed`) and
/// measures them against its true pose. Throws InputError if the left-out object is not an
/// object of the predictor's scene.
LeftOutPrediction predictLeftOutObject(const asr_ism_tree::TreeRecognizer& recognizer,
                                       const PosePredictor& predictor,
                                       const asr_common::Configuration& configuration,
                                       std::size_t left_out, std::size_t samples,
                                       std::uint32_t seed);

}  // namespace asr_pose_prediction
