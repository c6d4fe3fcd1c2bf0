#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "asr_robot_model/robot_description.hpp"

namespace asr_nbv {

/// The camera orientations the head can take at one tilt: the optical axis has one elevation
/// and the camera one height above the floor; headings (azimuths of the axis) are spread evenly.
struct TiltLevel {
  double tilt = 0.0;
  double elevation = 0.0;      // of the optical axis, radians
  double camera_height = 0.0;  // metres above the floor
  double first_heading = 0.0;  // radians
  double heading_step = 0.0;
  std::size_t first_orientation = 0;  // index of its first orientation
  std::size_t headings = 0;
};

/// Camera orientations sampled on the sphere within the tilt range: tilt levels about `step`
/// apart and, per level, headings about `step` apart on the circle of its elevation. The head
/// cannot roll the camera, so each orientation is one the head takes exactly. `seed` turns the
/// headings of each level by a fraction of a step (deterministic for a seed).
class CandidateOrientations {
 public:
  CandidateOrientations(const asr_robot_model::RobotDescription& robot, double step, unsigned seed);

  const std::vector<TiltLevel>& levels() const { return levels_; }
  std::size_t size() const { return rotations_.size(); }
  /// Rotation of camera_optical_frame in map, and its optical axis.
  const Eigen::Matrix3d& rotation(std::size_t index) const { return rotations_[index]; }
  const Eigen::Vector3d& axis(std::size_t index) const { return axes_[index]; }
  std::size_t levelOf(std::size_t index) const { return level_of_[index]; }

 private:
  std::vector<TiltLevel> levels_;
  std::vector<Eigen::Matrix3d> rotations_;
  std::vector<Eigen::Vector3d> axes_;
  std::vector<std::size_t> level_of_;
};

/// Points of a hexagonal lattice (hexagons of radius `radius`, centres 2 r cos 30 deg apart in a
/// row, rows 1.5 r apart) around `centre`, within `reach` of it (Chebyshev distance) and inside
/// the rectangle [low, high]; the centre first.
std::vector<Eigen::Vector2d> hexagonalLattice(const Eigen::Vector2d& centre, double radius,
                                              double reach, const Eigen::Vector2d& low,
                                              const Eigen::Vector2d& high);

}  // namespace asr_nbv
