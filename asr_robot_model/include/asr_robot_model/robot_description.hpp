#pragma once

#include <Eigen/Geometry>
#include <string>

namespace asr_robot_model {

/// A revolute joint of the pan-tilt unit: its axis (unit, in the joint frame), limits in radians
/// and top speed in radians per second, as the URDF gives them.
struct RevoluteJoint {
  std::string name;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  double lower = 0.0;
  double upper = 0.0;
  double velocity = 0.0;

  bool withinLimits(double angle) const { return angle >= lower && angle <= upper; }
};

/// A joint of the URDF between two frames, for publishing the robot's frames (tf): its fixed
/// origin in the parent link and, for a joint that moves, its unit axis.
struct UrdfJoint {
  std::string name;
  std::string parent;
  std::string child;
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
  bool moves = false;  // revolute or continuous (other moving joints are held at zero)
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
};

/// The kinematic chain from base_footprint to camera_optical_frame, read from a URDF:
///   base_footprint * base_to_pan * Rot(pan.axis, pan) * pan_to_tilt * Rot(tilt.axis, tilt)
///     * tilt_to_camera = camera_optical_frame
/// where each fixed transform is the product of the URDF's fixed joints and the revolute joint's
/// own origin. base_radius is the radius of base_link's collision cylinder (free-space checks).
struct RobotDescription {
  std::string source;  // the URDF file (for messages)
  Eigen::Isometry3d base_to_pan = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d pan_to_tilt = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d tilt_to_camera = Eigen::Isometry3d::Identity();
  RevoluteJoint pan;
  RevoluteJoint tilt;
  double base_radius = 0.0;
  std::vector<UrdfJoint> joints;  // every joint of the URDF, by name
};

/// Frame and joint names the suite's robots must use (REP 103/105).
inline constexpr const char* kBaseFrame = "base_footprint";
inline constexpr const char* kBaseLink = "base_link";
inline constexpr const char* kCameraFrame = "camera_optical_frame";
inline constexpr const char* kPanJoint = "ptu_pan_joint";
inline constexpr const char* kTiltJoint = "ptu_tilt_joint";

/// Reads the robot from a URDF file with urdfdom. Throws asr_common::InputError naming the file
/// and the field for an unreadable or malformed URDF, a missing frame or joint, a joint of the
/// wrong type or without limits and velocity, a chain from base_footprint to
/// camera_optical_frame that is not [fixed...] pan [fixed...] tilt [fixed...], a pan axis that
/// is not vertical in base_footprint, or base_link without a collision cylinder.
RobotDescription loadRobotDescription(const std::string& urdf_path);

/// The same from URDF text; `source` names it in messages.
RobotDescription parseRobotDescription(const std::string& urdf_xml, const std::string& source);

/// The shipped robot's URDF (asr_robot_model/urdf/asr_robot.urdf; see shippedFile).
std::string defaultRobotUrdf();

}  // namespace asr_robot_model
