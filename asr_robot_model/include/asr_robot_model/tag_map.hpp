#pragma once

#include <map>
#include <string>

#include "asr_common/object.hpp"
#include "asr_common/pose.hpp"

namespace asr_robot_model {

/// One AprilTag stuck to an object (config/tag_map.yaml documents the format).
struct TagPlacement {
  int id = 0;
  asr_common::ObjectKey object;
  double edge_length = 0.0;  // metres, outer edge of the black square
  /// The tag in the object's frame: centre, x right and y up as the tag is read, z out of its
  /// printed face.
  asr_common::Pose pose;
};

/// Which tag of a family belongs to which object, and where on it.
struct TagMap {
  std::string family = "tag36h11";
  std::map<int, TagPlacement> tags;

  /// The placement of tag `id`, or nullptr if the map does not know it.
  const TagPlacement* find(int id) const;
};

/// Reads a tag map (YAML or JSON). Throws asr_common::InputError naming the file and the field
/// for a malformed file, an unknown family, a negative or repeated id, a non-positive edge
/// length or an unnormalised orientation.
TagMap loadTagMap(const std::string& path);

/// The shipped tag map of the kitchen's objects (asr_robot_model/config/tag_map.yaml).
std::string defaultTagMap();

}  // namespace asr_robot_model
