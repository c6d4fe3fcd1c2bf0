#include "asr_ism/ros/demonstration_markers.hpp"

#include "asr_common/ros/marker_style.hpp"

namespace asr_ism::ros_interface {

using namespace asr_common::ros_interface;

using visualization_msgs::Marker;

visualization_msgs::MarkerArray demonstrationMarkers(const Demonstration& demonstration,
                                                     const std_msgs::Header& header) {
  visualization_msgs::MarkerArray markers;
  markers.markers.push_back(deleteAllMarker(header));
  int id = 0;
  const std::string& ns = demonstration.scene();
  for (std::size_t object = 0; object < demonstration.objectCount(); ++object) {
    const std_msgs::ColorRGBA color =
        hueColor(static_cast<double>(object) / demonstration.objectCount());
    Marker strip = newMarker(header, ns, id++, Marker::LINE_STRIP);
    strip.scale.x = 0.005;
    strip.color = color;
    for (const auto& pose : demonstration.trajectory(object)) {
      if (!pose) {  // not seen: end this strip, start another
        if (strip.points.size() >= 2)
          markers.markers.push_back(strip);
        strip.points.clear();
        strip.id = id++;
        continue;
      }
      strip.points.push_back(pointOf(pose->position));
    }
    if (strip.points.size() >= 2)
      markers.markers.push_back(strip);
    // A sphere and the object's name where it was seen last.
    for (std::size_t step = demonstration.stepCount(); step-- > 0;) {
      if (const auto& pose = demonstration.pose(step, object)) {
        Marker end = newMarker(header, ns, id++, Marker::SPHERE);
        end.pose.position = pointOf(pose->position);
        end.scale.x = end.scale.y = end.scale.z = 0.03;
        end.color = color;
        markers.markers.push_back(end);
        Marker label = newMarker(header, ns, id++, Marker::TEXT_VIEW_FACING);
        label.pose.position = pointOf(pose->position);
        label.pose.position.z += 0.05;
        label.scale.z = 0.03;
        label.color = color;
        label.text = demonstration.objects()[object].toString();
        markers.markers.push_back(label);
        break;
      }
    }
  }
  return markers;
}

}  // namespace asr_ism::ros_interface
