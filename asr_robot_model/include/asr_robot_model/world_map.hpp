#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "asr_robot_model/world.hpp"

namespace asr_robot_model {

/// The furniture and objects of a world as an OctoMap of occupied voxels (their box surfaces,
/// which is what rays and the base footprint meet), answering free space for the base and line
/// of sight for the camera. OctoMap stays behind this interface.
class WorldMap {
 public:
  /// `resolution`: voxel edge in metres (> 0). `base_radius`: of the base's footprint;
  /// `base_height`: how high above the floor the robot's body reaches (furniture above it, such
  /// as a shelf board, does not block the base).
  WorldMap(const World& world, double resolution, double base_radius, double base_height = 2.0);
  ~WorldMap();
  WorldMap(WorldMap&&) noexcept;
  WorldMap& operator=(WorldMap&&) noexcept;

  /// True if the base's disc at (x, y) lies in the room and meets no occupied voxel below
  /// base_height. A lookup in a grid of the room (cells of the voxel size) computed once from
  /// the OctoMap: a cell is blocked if a point in it lies within the base radius of an occupied
  /// voxel's footprint, so the answer errs on the safe side by at most a cell diagonal.
  bool baseIsFree(double x, double y) const;

  /// True if the segment from `eye` to `target`'s centre crosses no occupied voxel but those of
  /// the target itself (voxels whose centre lies within half a voxel diagonal of its box).
  /// A segment that passes farther than a voxel diagonal from every box of the world is free
  /// without a ray cast; the ray cast looks its voxels up in a grid of the occupied ones.
  bool lineOfSight(const Eigen::Vector3d& eye, const Box& target) const;
  /// lineOfSight by the ray cast through the OctoMap alone, always: the reference its shortcut
  /// and its grid are tested against.
  bool lineOfSightByRayCast(const Eigen::Vector3d& eye, const Box& target) const;

  double resolution() const;
  /// Centres of the occupied voxels (for display).
  std::vector<Eigen::Vector3d> occupiedVoxels() const;

 private:
  struct Octree;
  void computeBaseFootprintGrid();

  std::unique_ptr<Octree> octree_;
  std::vector<bool> base_blocked_;  // row-major cells over the room
  int cells_x_ = 0, cells_y_ = 0;
  Eigen::Vector2d room_min_, room_max_;
  double base_radius_, base_height_;
};

}  // namespace asr_robot_model
