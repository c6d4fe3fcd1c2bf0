#include "asr_robot_model/inverse_kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "asr_common/input_error.hpp"
#include "asr_robot_model/forward_kinematics.hpp"

namespace asr_robot_model {
namespace {

// Grid over the pan range, then golden-section refinement around the best grid point.
constexpr int kPanGridIntervals = 16;
constexpr int kGoldenIterations = 24;
// Angles this close outside a joint limit are rounding of a limit value, not a violation.
constexpr double kLimitRounding = 1e-9;

double degrees(double radians) {
  return radians * 180.0 / M_PI;
}

IkResult refused(Refusal reason, const std::string& explanation) {
  IkResult result;
  result.reason = reason;
  result.explanation = explanation;
  return result;
}

}  // namespace

const char* refusalName(Refusal refusal) {
  switch (refusal) {
    case Refusal::kNone:
      return "";
    case Refusal::kInvalidPose:
      return "invalid_pose";
    case Refusal::kTiltLimit:
      return "tilt_limit";
    case Refusal::kHeight:
      return "height";
    case Refusal::kBaseCollision:
      return "base_collision";
  }
  return "unknown";
}

InverseKinematics::InverseKinematics(RobotDescription robot, MotionSpeeds speeds,
                                     double height_tolerance)
    : robot_(std::move(robot)), speeds_(speeds), height_tolerance_(height_tolerance) {
  checkSpeeds(speeds_);
  pan_sign_ = (robot_.base_to_pan.linear() * robot_.pan.axis).z() > 0.0 ? 1.0 : -1.0;
  // The optical axis at pan 0 in base_footprint is R0 Rot(a, tilt) v (Rodrigues' formula), so
  // its z component is a cos(tilt) + b sin(tilt) + c; pan and yaw turn about the vertical and
  // leave it alone.
  const Eigen::Matrix3d r0 = robot_.base_to_pan.linear() * robot_.pan_to_tilt.linear();
  const Eigen::Vector3d a = robot_.tilt.axis;
  const Eigen::Vector3d v = robot_.tilt_to_camera.linear() * Eigen::Vector3d::UnitZ();
  elevation_a_ = (r0 * (v - a * a.dot(v))).z();
  elevation_b_ = (r0 * a.cross(v)).z();
  elevation_c_ = (r0 * a).z() * a.dot(v);
  if (std::hypot(elevation_a_, elevation_b_) < 1e-9)
    throw asr_common::InputError(robot_.source + ": joint '" + robot_.tilt.name +
                                 "' axis: tilting does not change the viewing elevation");
}

std::vector<double> InverseKinematics::tiltsForElevation(double elevation_sine) const {
  // a cos t + b sin t = r cos(t - phi) = elevation_sine - c.
  const double r = std::hypot(elevation_a_, elevation_b_);
  const double phi = std::atan2(elevation_b_, elevation_a_);
  const double cosine = (elevation_sine - elevation_c_) / r;
  std::vector<double> tilts;
  if (std::abs(cosine) > 1.0 + 1e-12)
    return tilts;
  const double offset = std::acos(std::clamp(cosine, -1.0, 1.0));
  for (double candidate : {phi + offset, phi - offset}) {
    double tilt = wrapAngle(candidate);
    if (tilt < robot_.tilt.lower && tilt > robot_.tilt.lower - kLimitRounding)
      tilt = robot_.tilt.lower;
    if (tilt > robot_.tilt.upper && tilt < robot_.tilt.upper + kLimitRounding)
      tilt = robot_.tilt.upper;
    if (robot_.tilt.withinLimits(tilt) && (tilts.empty() || std::abs(tilts[0] - tilt) > 1e-12))
      tilts.push_back(tilt);
  }
  return tilts;
}

// The state with this pan and tilt whose camera is at `position` looking with `heading` (the
// turn about the vertical from the pan-0 yaw-0 camera to the requested one).
// cameraInBase(pan, tilt) = [Rz(s pan) R_A R_M, t_A + Rz(s pan) w] with w = R_A t_M the camera
// position at pan 0 relative to the pan joint, `camera_offset` here.
RobotState InverseKinematics::stateFor(double pan, double tilt,
                                       const Eigen::Vector3d& camera_offset,
                                       const Eigen::Vector3d& position, double heading) const {
  const Eigen::Vector3d t_a = robot_.base_to_pan.translation();
  const Eigen::Vector3d& w = camera_offset;
  RobotState state;
  state.pan = pan;
  state.tilt = tilt;
  state.yaw = wrapAngle(heading - pan_sign_ * pan);
  const Eigen::Vector2d base_offset =
      Eigen::Rotation2Dd(state.yaw) * t_a.head<2>() + Eigen::Rotation2Dd(heading) * w.head<2>();
  state.x = position.x() - base_offset.x();
  state.y = position.y() - base_offset.y();
  return state;
}

// Over the pan range, the cheapest state to reach from `from` with a free base; false if every
// sampled base pose collides.
bool InverseKinematics::cheapestPan(double tilt, const Eigen::Vector3d& position, double heading,
                                    const RobotState& from, const BaseIsFree& base_is_free,
                                    RobotState& best, double& best_seconds) const {
  const Eigen::Vector3d offset =
      cameraInBase(robot_, 0.0, tilt).translation() - robot_.base_to_pan.translation();
  bool found = false;
  double best_pan = 0.0;
  auto consider = [&](double pan) {
    const RobotState state = stateFor(pan, tilt, offset, position, heading);
    const double seconds = motionBetween(from, state, speeds_).seconds;
    if (seconds >= best_seconds)
      return seconds;  // no better: its free space need not be looked up
    if (base_is_free && !base_is_free(state.x, state.y, state.yaw))
      return std::numeric_limits<double>::infinity();
    best_seconds = seconds;
    best = state;
    best_pan = pan;
    found = true;
    return seconds;
  };
  const double lower = robot_.pan.lower;
  const double step = (robot_.pan.upper - lower) / kPanGridIntervals;
  for (int i = 0; i <= kPanGridIntervals; ++i)
    consider(i == kPanGridIntervals ? robot_.pan.upper : lower + i * step);
  if (!found)
    return false;
  // Golden-section search in the grid cells either side of the best grid point.
  const double golden = (std::sqrt(5.0) - 1.0) / 2.0;
  double left = std::max(lower, best_pan - step);
  double right = std::min(robot_.pan.upper, best_pan + step);
  double inner_left = right - golden * (right - left);
  double inner_right = left + golden * (right - left);
  double cost_left = consider(inner_left);
  double cost_right = consider(inner_right);
  for (int i = 0; i < kGoldenIterations; ++i) {
    if (cost_left <= cost_right) {
      right = inner_right;
      inner_right = inner_left;
      cost_right = cost_left;
      inner_left = right - golden * (right - left);
      cost_left = consider(inner_left);
    } else {
      left = inner_left;
      inner_left = inner_right;
      cost_left = cost_right;
      inner_right = left + golden * (right - left);
      cost_right = consider(inner_right);
    }
  }
  return true;
}

IkResult InverseKinematics::solve(const Eigen::Vector3d& position,
                                  const Eigen::Quaterniond& orientation, const RobotState& from,
                                  const BaseIsFree& base_is_free) const {
  checkFinite(from, "current robot state");
  asr_common::Pose target;
  try {
    target = asr_common::validatedPose(position, orientation, "requested camera pose");
  } catch (const asr_common::InputError& error) {
    return refused(Refusal::kInvalidPose, error.what());
  }
  const Eigen::Vector3d direction = target.orientation * Eigen::Vector3d::UnitZ();
  const std::vector<double> tilts = tiltsForElevation(direction.z());
  std::ostringstream why;
  if (tilts.empty()) {
    why << "viewing elevation " << degrees(std::asin(std::clamp(direction.z(), -1.0, 1.0)))
        << " deg needs a tilt outside " << degrees(robot_.tilt.lower) << ".."
        << degrees(robot_.tilt.upper) << " deg";
    return refused(Refusal::kTiltLimit, why.str());
  }
  RobotState best;
  double best_seconds = std::numeric_limits<double>::infinity();
  bool height_matched = false;
  for (double tilt : tilts) {
    const Eigen::Isometry3d at_zero = cameraInBase(robot_, 0.0, tilt);
    if (std::abs(at_zero.translation().z() - target.position.z()) > height_tolerance_) {
      why << "camera height " << target.position.z() << " m: at this viewing elevation the head "
          << "holds the camera at " << at_zero.translation().z() << " m; ";
      continue;
    }
    height_matched = true;
    const Eigen::Vector3d zero_direction = at_zero.linear() * Eigen::Vector3d::UnitZ();
    const double heading = std::atan2(direction.y(), direction.x()) -
                           std::atan2(zero_direction.y(), zero_direction.x());
    cheapestPan(tilt, target.position, heading, from, base_is_free, best, best_seconds);
  }
  if (!height_matched)
    return refused(Refusal::kHeight, why.str().substr(0, why.str().size() - 2));
  if (!std::isfinite(best_seconds)) {
    why << "every base pose that gives this view collides (base radius " << robot_.base_radius
        << " m)";
    return refused(Refusal::kBaseCollision, why.str());
  }
  IkResult result;
  result.reachable = true;
  result.state = best;
  result.camera = cameraPose(robot_, best);
  result.seconds = best_seconds;
  result.roll_difference = asr_common::angleBetween(result.camera.orientation, target.orientation);
  return result;
}

}  // namespace asr_robot_model
