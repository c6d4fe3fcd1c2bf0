#pragma once

#include <Eigen/Geometry>
#include <string>

namespace asr_common {

/// A 6-DoF pose: position in metres and a unit quaternion with w >= 0.
struct Pose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();

  Pose() = default;
  Pose(const Eigen::Vector3d& position_in, const Eigen::Quaterniond& orientation_in);

  static Pose identity() { return Pose(); }
};

/// a * b: the pose b, given in the frame of a, expressed in a's parent frame.
Pose compose(const Pose& a, const Pose& b);

/// The inverse transform of a pose.
Pose inverse(const Pose& pose);

/// The pose of `to` expressed in the frame of `from`: inverse(from) * to.
Pose relativePose(const Pose& from, const Pose& to);

/// Angle in radians of the rotation between two unit quaternions, in [0, pi].
double angleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);

/// Returns q scaled to unit length with w >= 0 (q and -q are the same rotation). A quaternion
/// that is unit up to rounding is not rescaled, so the function is idempotent.
Eigen::Quaterniond canonicalQuaternion(const Eigen::Quaterniond& q);

/// Validates a pose a user supplied and returns it canonicalised. Throws InputError naming
/// `what` for non-finite values, a coordinate beyond kMaxCoordinate (input_limits.hpp), a zero
/// quaternion or one whose norm is far from 1 (more than
/// `norm_tolerance`); small rounding deviations are normalised away.
Pose validatedPose(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
                   const std::string& what, double norm_tolerance = 1e-3);

/// True if the two poses are equal up to `position_tolerance` metres and
/// `angle_tolerance` radians.
bool approximatelyEqual(const Pose& a, const Pose& b, double position_tolerance = 1e-9,
                        double angle_tolerance = 1e-9);

}  // namespace asr_common
