#pragma once

#include <Eigen/Geometry>
#include <functional>
#include <string>
#include <vector>

#include "asr_common/pose.hpp"
#include "asr_robot_model/motion_model.hpp"
#include "asr_robot_model/robot_description.hpp"
#include "asr_robot_model/robot_state.hpp"

namespace asr_robot_model {

/// Why a requested camera pose cannot be taken.
enum class Refusal {
  kNone,           // reachable
  kInvalidPose,    // not finite, or a quaternion far from unit length
  kTiltLimit,      // no tilt within the limits gives the viewing direction's elevation
  kHeight,         // at that elevation the head holds the camera at another height
  kBaseCollision,  // every base pose that gives the view collides (room, furniture)
};

/// "", "invalid_pose", "tilt_limit", "height", "base_collision".
const char* refusalName(Refusal refusal);

/// True if the base may stand at (x, y) with heading yaw; an empty function allows everywhere.
using BaseIsFree = std::function<bool(double x, double y, double yaw)>;

struct IkResult {
  bool reachable = false;
  Refusal reason = Refusal::kNone;
  std::string explanation;  // empty when reachable
  RobotState state;         // the state reached (when reachable)
  asr_common::Pose camera;  // forward kinematics of `state`
  double seconds = 0.0;     // motion time from the current state
  /// Rotation about the optical axis between the requested and the reached orientation, radians:
  /// the head cannot roll the camera, so the requested roll is not reproduced (the viewing
  /// direction and position are).
  double roll_difference = 0.0;
};

/// Exact inverse kinematics of the pan-tilt head on the mobile base. The elevation of the
/// viewing direction fixes the tilt (up to two solutions within the limits), which fixes the
/// camera height; the heading is shared between base yaw and pan, and the base position follows.
/// Of this one-parameter family (pan over its range), the state cheapest to reach from the
/// current state by the motion model, with a free base, is returned.
class InverseKinematics {
 public:
  /// `height_tolerance`: metres the requested camera height may differ from the head's.
  InverseKinematics(RobotDescription robot, MotionSpeeds speeds, double height_tolerance = 1e-6);

  IkResult solve(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
                 const RobotState& from, const BaseIsFree& base_is_free = {}) const;

  const RobotDescription& robot() const { return robot_; }
  const MotionSpeeds& speeds() const { return speeds_; }

 private:
  std::vector<double> tiltsForElevation(double elevation_sine) const;
  RobotState stateFor(double pan, double tilt, const Eigen::Vector3d& camera_offset,
                      const Eigen::Vector3d& position, double heading) const;
  bool cheapestPan(double tilt, const Eigen::Vector3d& position, double heading,
                   const RobotState& from, const BaseIsFree& base_is_free, RobotState& best,
                   double& best_seconds) const;

  RobotDescription robot_;
  MotionSpeeds speeds_;
  double height_tolerance_;
  double pan_sign_;  // +1 if the pan axis points up in base_footprint, -1 if down
  // Elevation of the optical axis in base_footprint: sine = a cos(tilt) + b sin(tilt) + c.
  double elevation_a_, elevation_b_, elevation_c_;
};

}  // namespace asr_robot_model
