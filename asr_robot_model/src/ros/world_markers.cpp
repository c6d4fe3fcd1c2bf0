#include "asr_robot_model/ros/world_markers.hpp"

#include <cmath>

#include "asr_common/ros/marker_style.hpp"
#include "asr_common/ros/object_estimate_message.hpp"

namespace asr_robot_model::ros_interface {
namespace {

using namespace asr_common::ros_interface;
using visualization_msgs::Marker;

Marker boxMarker(const Box& box, const std_msgs::Header& header, const std::string& ns, int id,
                 const std_msgs::ColorRGBA& color) {
  Marker marker = newMarker(header, ns, id, Marker::CUBE);
  marker.pose = toPoseMessage(box.pose);
  marker.scale.x = box.size.x();
  marker.scale.y = box.size.y();
  marker.scale.z = box.size.z();
  marker.color = color;
  return marker;
}

Marker voxelMarker(const WorldMap& map, const std_msgs::Header& header) {
  Marker marker = newMarker(header, "voxels", 0, Marker::CUBE_LIST);
  marker.scale.x = marker.scale.y = marker.scale.z = map.resolution();
  marker.color = rgbaColor(0.3, 0.3, 0.3, 0.5);
  for (const Eigen::Vector3d& centre : map.occupiedVoxels())
    marker.points.push_back(pointOf(centre));
  return marker;
}

}  // namespace

Marker frustumMarker(const Frustum& frustum, std_msgs::Header header, const std::string& frame) {
  header.frame_id = frame;
  Marker marker = newMarker(header, "frustum", 0, Marker::LINE_LIST);
  marker.scale.x = 0.01;
  marker.color = rgbaColor(1.0, 0.8, 0.0, 1.0);
  auto corner = [&](double z, int sx, int sy) {
    return Eigen::Vector3d(sx * z * std::tan(frustum.fovx() / 2),
                           sy * z * std::tan(frustum.fovy() / 2), z);
  };
  const int signs[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    for (const double z : {frustum.near(), frustum.far()}) {
      marker.points.push_back(pointOf(corner(z, signs[i][0], signs[i][1])));
      marker.points.push_back(pointOf(corner(z, signs[j][0], signs[j][1])));
    }
    marker.points.push_back(pointOf(corner(frustum.near(), signs[i][0], signs[i][1])));
    marker.points.push_back(pointOf(corner(frustum.far(), signs[i][0], signs[i][1])));
  }
  return marker;
}

visualization_msgs::MarkerArray worldMarkers(const World& world, const WorldMap& map,
                                             const Frustum& frustum, const std_msgs::Header& header,
                                             const std::string& camera_frame) {
  visualization_msgs::MarkerArray markers;
  markers.markers.push_back(deleteAllMarker(header));
  int id = 0;
  for (const Furniture& piece : world.furniture)
    markers.markers.push_back(
        boxMarker(piece.box, header, "furniture", id++, rgbaColor(0.55, 0.4, 0.25, 0.9)));
  id = 0;
  for (const WorldObject& object : world.objects) {
    const double hue = static_cast<double>(id) / std::max<std::size_t>(world.objects.size(), 1);
    markers.markers.push_back(boxMarker(object.box, header, "objects", id, hueColor(hue, 0.35)));
    Marker name = newMarker(header, "object_names", id++, Marker::TEXT_VIEW_FACING);
    name.pose = toPoseMessage(object.box.pose);
    name.pose.position.z += object.box.size.z() / 2 + 0.05;
    name.scale.z = 0.06;
    name.color = rgbaColor(1.0, 1.0, 1.0, 0.8);
    name.text = object.key.type + ":" + object.key.id;
    markers.markers.push_back(name);
  }
  markers.markers.push_back(voxelMarker(map, header));
  markers.markers.push_back(frustumMarker(frustum, header, camera_frame));
  return markers;
}

}  // namespace asr_robot_model::ros_interface
