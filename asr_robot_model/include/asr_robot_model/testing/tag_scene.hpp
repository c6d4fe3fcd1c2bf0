// Test and benchmark support: a board carrying AprilTags in an empty room, and camera poses
// looking at it from a chosen distance and angle, so rendered views have exactly known poses.
#pragma once

#include <cmath>
#include <string>

#include "asr_common/pose.hpp"
#include "asr_robot_model/tag_map.hpp"
#include "asr_robot_model/world.hpp"

namespace asr_robot_model::testing {

/// camera_optical_frame at `eye` looking at `target` (z forward, x right, y down; the image's
/// up is world +z where it can be).
inline asr_common::Pose lookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target) {
  const Eigen::Vector3d forward = (target - eye).normalized();
  Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ());
  if (right.norm() < 1e-6)
    right = Eigen::Vector3d::UnitX();
  right.normalize();
  const Eigen::Vector3d down = forward.cross(right);
  Eigen::Matrix3d axes;
  axes << right, down, forward;
  return asr_common::Pose(eye, asr_common::canonicalQuaternion(Eigen::Quaterniond(axes)));
}

/// A camera `distance` metres from `target`, `off_axis` radians away from the direction
/// `normal`, turned `azimuth` radians about it.
inline asr_common::Pose viewOf(const Eigen::Vector3d& target, const Eigen::Vector3d& normal,
                               double distance, double off_axis, double azimuth) {
  Eigen::Vector3d side = normal.unitOrthogonal();
  side = Eigen::AngleAxisd(azimuth, normal) * side;
  const Eigen::Vector3d direction = std::cos(off_axis) * normal + std::sin(off_axis) * side;
  return lookAt(target + distance * direction, target);
}

/// A thin board (object "Board" "0") standing upright at (2, 0, 1) in an empty room, its face
/// turned to the world's -x, carrying tag 0 of `edge` metres at its centre.
struct TagBoard {
  World world;
  TagMap tags;
  asr_common::Pose board;  // in the world
  Eigen::Vector3d face_normal = -Eigen::Vector3d::UnitX();

  explicit TagBoard(double edge = 0.1) {
    world.room_min = {-5, -5};
    world.room_max = {5, 5};
    // The board's frame: z out of its face (towards -x of the world), y up.
    Eigen::Matrix3d axes;
    axes << -Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitX();
    board = asr_common::Pose({2, 0, 1}, asr_common::canonicalQuaternion(Eigen::Quaterniond(axes)));
    WorldObject object;
    object.key = {"Board", "0"};
    object.box.pose = board;
    object.box.size = {0.4, 0.4, 0.01};
    world.objects.push_back(object);
    addTag(0, edge, {0, 0, 0.005});
  }

  /// Adds tag `id` on the board's face at `position` (board frame, z = 0.005 is the face).
  void addTag(int id, double edge, const Eigen::Vector3d& position) {
    TagPlacement tag;
    tag.id = id;
    tag.object = {"Board", "0"};
    tag.edge_length = edge;
    tag.pose.position = position;
    tags.tags[id] = tag;
  }

  Eigen::Vector3d centre() const { return board.position; }
};

}  // namespace asr_robot_model::testing
