#pragma once

#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>

#include "asr_robot_model/frustum.hpp"
#include "asr_robot_model/world.hpp"
#include "asr_robot_model/world_map.hpp"

// rviz markers of the simulated world (no octomap_msgs in Debian, so the OctoMap is drawn as a
// cube list of its occupied voxels).
namespace asr_robot_model::ros_interface {

/// The frustum's 12 edges as a line list in `frame` (the camera's optical frame), namespace
/// "frustum", id 0, yellow.
visualization_msgs::Marker frustumMarker(const Frustum& frustum, std_msgs::Header header,
                                         const std::string& frame);

/// Furniture (boxes, namespace "furniture"), the true object poses (dimmed boxes, "objects",
/// with their names as text, "object_names"), the occupied voxels ("voxels") in `header`'s frame
/// (map), and the camera frustum ("frustum", lines in `camera_frame`). Opens with DELETEALL.
visualization_msgs::MarkerArray worldMarkers(const World& world, const WorldMap& map,
                                             const Frustum& frustum, const std_msgs::Header& header,
                                             const std::string& camera_frame);

}  // namespace asr_robot_model::ros_interface
