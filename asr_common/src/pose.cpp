#include "asr_common/pose.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "asr_common/input_error.hpp"
#include "asr_common/input_limits.hpp"

namespace asr_common {

Pose::Pose(const Eigen::Vector3d& position_in, const Eigen::Quaterniond& orientation_in)
    : position(position_in), orientation(canonicalQuaternion(orientation_in)) {}

Pose compose(const Pose& a, const Pose& b) {
  return Pose(a.position + a.orientation * b.position, a.orientation * b.orientation);
}

Pose inverse(const Pose& pose) {
  const Eigen::Quaterniond inverse_rotation = pose.orientation.conjugate();
  return Pose(-(inverse_rotation * pose.position), inverse_rotation);
}

Pose relativePose(const Pose& from, const Pose& to) {
  return compose(inverse(from), to);
}

double angleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  // atan2 keeps full precision for tiny angles, where acos of the dot product does not.
  const Eigen::Quaterniond difference = a.conjugate() * b;
  return 2.0 * std::atan2(difference.vec().norm(), std::abs(difference.w()));
}

Eigen::Quaterniond canonicalQuaternion(const Eigen::Quaterniond& q) {
  // A quaternion that is unit up to rounding is kept bit for bit: normalising it again would
  // change the last bits of about a third of them, so poses would not survive a round trip
  // through a file exactly and canonicalQuaternion would not be idempotent.
  const bool unit_already =
      std::abs(q.squaredNorm() - 1.0) <= 8.0 * std::numeric_limits<double>::epsilon();
  Eigen::Quaterniond unit = unit_already ? q : q.normalized();
  if (unit.w() < 0.0) {
    unit.coeffs() = -unit.coeffs();
  }
  return unit;
}

Pose validatedPose(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
                   const std::string& what, double norm_tolerance) {
  if (!position.allFinite()) {
    throw InputError(what + ": position is not finite (NaN or infinity)");
  }
  if (position.cwiseAbs().maxCoeff() > kMaxCoordinate) {
    std::ostringstream message;
    message << what << ": position (" << position.x() << ", " << position.y() << ", "
            << position.z() << ") is more than " << kMaxCoordinate
            << " m from the origin in a coordinate (the suite's limit)";
    throw InputError(message.str());
  }
  if (!orientation.coeffs().allFinite()) {
    throw InputError(what + ": orientation is not finite (NaN or infinity)");
  }
  const double norm = orientation.norm();
  if (norm < 1e-12) {
    throw InputError(what + ": orientation is a zero quaternion");
  }
  if (std::abs(norm - 1.0) > norm_tolerance) {
    std::ostringstream message;
    message << what << ": orientation quaternion is not normalised (norm " << norm << ")";
    throw InputError(message.str());
  }
  return Pose(position, orientation);
}

bool approximatelyEqual(const Pose& a, const Pose& b, double position_tolerance,
                        double angle_tolerance) {
  return (a.position - b.position).norm() <= position_tolerance &&
         angleBetween(a.orientation, b.orientation) <= angle_tolerance;
}

}  // namespace asr_common
