#pragma once

#include <vector>

#include "asr_common/pose.hpp"

namespace asr_pose_prediction {

/// Where a cloud of predicted poses of one object lies and how far it spreads.
struct PoseCloudSummary {
  std::size_t count = 0;
  Eigen::Vector3d mean_position = Eigen::Vector3d::Zero();
  /// Root mean square of the distances from the mean position, metres.
  double position_rms = 0.0;
  double position_max = 0.0;
  /// The rotation closest to all orientations (chordal mean: the principal eigenvector of the sum
  /// of q q^T, which does not depend on the signs of the quaternions).
  Eigen::Quaterniond mean_orientation = Eigen::Quaterniond::Identity();
  /// Root mean square and maximum of the angles from the mean orientation, radians.
  double angle_rms = 0.0;
  double angle_max = 0.0;
};

/// Throws InputError for an empty cloud.
PoseCloudSummary summarizePoseCloud(const std::vector<asr_common::Pose>& poses);

}  // namespace asr_pose_prediction
