#include "asr_state_machine/ros/search_markers.hpp"

#include "asr_common/ros/marker_style.hpp"
#include "asr_common/ros/object_estimate_message.hpp"
#include "asr_robot_model/ros/world_markers.hpp"

namespace asr_state_machine::ros_interface {

namespace {

using asr_common::ros_interface::newMarker;
using asr_common::ros_interface::pointOf;
using asr_common::ros_interface::rgbaColor;
using asr_common::ros_interface::toPoseMessage;
using visualization_msgs::Marker;

Marker pathMarker(const std::vector<VisitedView>& views, const std_msgs::Header& header) {
  Marker path = newMarker(header, "path", 0, Marker::LINE_STRIP);
  path.scale.x = 0.03;
  path.color = rgbaColor(0.1, 0.4, 1.0);
  for (const VisitedView& view : views) {
    Eigen::Vector3d on_floor = view.camera.position;
    on_floor.z() = 0.02;
    path.points.push_back(pointOf(on_floor));
  }
  return path;
}

}  // namespace

visualization_msgs::MarkerArray searchMarkers(const WorldModel& world,
                                              const asr_robot_model::Frustum& frustum,
                                              const std_msgs::Header& header) {
  visualization_msgs::MarkerArray markers;
  markers.markers.push_back(asr_common::ros_interface::deleteAllMarker(header));
  const std::vector<VisitedView>& views = world.visitedViews();
  if (views.size() >= 2)
    markers.markers.push_back(pathMarker(views, header));
  for (std::size_t v = 0; v < views.size(); ++v) {
    // The frustum's lines are in the camera's frame: placed at the view's camera pose in map.
    Marker view = asr_robot_model::ros_interface::frustumMarker(frustum, header, header.frame_id);
    view.header = header;
    view.ns = "views";
    view.id = static_cast<int>(v);
    view.pose = toPoseMessage(views[v].camera);
    view.scale.x = 0.01;
    view.color = v + 1 == views.size() ? rgbaColor(1.0, 0.9, 0.0) : rgbaColor(0.6, 0.6, 0.6, 0.6);
    markers.markers.push_back(view);
  }
  int id = 0;
  for (const FoundObject& found : world.foundObjects()) {
    Marker box = newMarker(header, "found", id, Marker::CUBE);
    box.pose = toPoseMessage(found.pose);
    box.scale.x = box.scale.y = box.scale.z = 0.08;
    box.color = rgbaColor(0.1, 0.9, 0.2, 0.9);
    markers.markers.push_back(box);
    Marker name = newMarker(header, "found_names", id, Marker::TEXT_VIEW_FACING);
    name.pose.position = pointOf(found.pose.position + Eigen::Vector3d(0, 0, 0.12));
    name.scale.z = 0.06;
    name.color = rgbaColor(1.0, 1.0, 1.0);
    name.text = found.key.toString();
    markers.markers.push_back(name);
    ++id;
  }
  return markers;
}

}  // namespace asr_state_machine::ros_interface
