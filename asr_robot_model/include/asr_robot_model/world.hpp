#pragma once

#include <Eigen/Geometry>
#include <map>
#include <string>
#include <vector>

#include "asr_common/object.hpp"
#include "asr_common/pose.hpp"
#include "asr_robot_model/robot_state.hpp"

namespace asr_robot_model {

/// An oriented box: centre pose and full edge lengths along its own axes.
struct Box {
  asr_common::Pose pose;
  Eigen::Vector3d size = Eigen::Vector3d::Zero();

  /// True if the point (in the box's parent frame) is inside or on the box, grown by `margin`.
  bool contains(const Eigen::Vector3d& point, double margin = 0.0) const;
  /// The 8 corners in the parent frame.
  std::vector<Eigen::Vector3d> corners() const;
};

/// What the catalogue says of an object type: its box size, the object-frame directions it can
/// be recognised from (none: from everywhere), and an optional mesh resource for display.
struct ObjectType {
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> normals;
  std::string mesh;
};
using ObjectCatalogue = std::map<std::string, ObjectType>;

struct Furniture {
  std::string name;
  Box box;
};

struct WorldObject {
  asr_common::ObjectKey key;
  Box box;
  std::vector<Eigen::Vector3d> normals;  // unit, object frame
};

/// A simulated world (docs/robot.md): the floor rectangle the base stays in, static furniture
/// boxes, the objects to find and the robot's start state, all in `frame` (map).
struct World {
  std::string frame = "map";
  Eigen::Vector2d room_min = Eigen::Vector2d::Zero();
  Eigen::Vector2d room_max = Eigen::Vector2d::Zero();
  std::vector<Furniture> furniture;
  std::vector<WorldObject> objects;
  RobotState robot;
};

/// Reads config/object_types.yaml (or any catalogue of that format). Throws
/// asr_common::InputError naming the file and the field if it is malformed.
ObjectCatalogue loadObjectCatalogue(const std::string& path);

/// The shipped catalogue (asr_robot_model/config/object_types.yaml; see shippedFile).
std::string defaultObjectCatalogue();

/// Reads a world file (YAML or JSON). Objects without a size or normals take those of their
/// type in the catalogue. Throws asr_common::InputError naming the file and the field for a
/// malformed world, an unknown type without a size, non-positive sizes, zero normals, a room
/// that is empty, two objects with one type and id, or an object whose centre lies inside
/// furniture.
World loadWorld(const std::string& path, const ObjectCatalogue& catalogue);

}  // namespace asr_robot_model
