#include "asr_pose_prediction/pose_cloud_summary.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "asr_common/input_error.hpp"

namespace asr_pose_prediction {

PoseCloudSummary summarizePoseCloud(const std::vector<asr_common::Pose>& poses) {
  if (poses.empty())
    throw asr_common::InputError("no predicted pose to summarise");
  PoseCloudSummary summary;
  summary.count = poses.size();
  const double count = static_cast<double>(poses.size());
  Eigen::Matrix4d scatter = Eigen::Matrix4d::Zero();
  for (const asr_common::Pose& pose : poses) {
    summary.mean_position += pose.position / count;
    const Eigen::Vector4d q = pose.orientation.coeffs();
    scatter += q * q.transpose();
  }
  // Eigenvalues come in increasing order: the last eigenvector is the chordal mean.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> solver(scatter);
  const Eigen::Vector4d mean = solver.eigenvectors().col(3);
  summary.mean_orientation =
      asr_common::canonicalQuaternion(Eigen::Quaterniond(mean(3), mean(0), mean(1), mean(2)));

  double squared_distances = 0.0;
  double squared_angles = 0.0;
  for (const asr_common::Pose& pose : poses) {
    const double distance = (pose.position - summary.mean_position).norm();
    const double angle = asr_common::angleBetween(summary.mean_orientation, pose.orientation);
    squared_distances += distance * distance;
    squared_angles += angle * angle;
    summary.position_max = std::max(summary.position_max, distance);
    summary.angle_max = std::max(summary.angle_max, angle);
  }
  summary.position_rms = std::sqrt(squared_distances / count);
  summary.angle_rms = std::sqrt(squared_angles / count);
  return summary;
}

}  // namespace asr_pose_prediction
