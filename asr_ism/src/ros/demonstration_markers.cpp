#include "asr_ism/ros/demonstration_markers.hpp"

#include <cmath>

namespace asr_ism::ros_interface {
namespace {

using visualization_msgs::Marker;

// Evenly spread hues, full saturation.
std_msgs::ColorRGBA objectColor(std::size_t object, std::size_t count) {
  const double hue =
      6.0 * static_cast<double>(object) / static_cast<double>(std::max<std::size_t>(1, count));
  const double rising = hue - std::floor(hue);
  const double r[] = {1, 1 - rising, 0, 0, rising, 1};
  const double g[] = {rising, 1, 1, 1 - rising, 0, 0};
  const double b[] = {0, 0, rising, 1, 1, 1 - rising};
  const int sector = static_cast<int>(hue) % 6;
  std_msgs::ColorRGBA color;
  color.r = static_cast<float>(r[sector]);
  color.g = static_cast<float>(g[sector]);
  color.b = static_cast<float>(b[sector]);
  color.a = 1.0f;
  return color;
}

Marker newMarker(const std_msgs::Header& header, const std::string& ns, int id, int type) {
  Marker marker;
  marker.header = header;
  marker.ns = ns;
  marker.id = id;
  marker.type = type;
  marker.action = Marker::ADD;
  marker.pose.orientation.w = 1.0;
  return marker;
}

geometry_msgs::Point pointOf(const Pose& pose) {
  geometry_msgs::Point point;
  point.x = pose.position.x();
  point.y = pose.position.y();
  point.z = pose.position.z();
  return point;
}

}  // namespace

visualization_msgs::MarkerArray demonstrationMarkers(const Demonstration& demonstration,
                                                     const std_msgs::Header& header) {
  visualization_msgs::MarkerArray markers;
  Marker clear;
  clear.header = header;
  clear.action = Marker::DELETEALL;
  markers.markers.push_back(clear);
  int id = 0;
  const std::string& ns = demonstration.scene();
  for (std::size_t object = 0; object < demonstration.objectCount(); ++object) {
    const std_msgs::ColorRGBA color = objectColor(object, demonstration.objectCount());
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
      strip.points.push_back(pointOf(*pose));
    }
    if (strip.points.size() >= 2)
      markers.markers.push_back(strip);
    // A sphere and the object's name where it was seen last.
    for (std::size_t step = demonstration.stepCount(); step-- > 0;) {
      if (const auto& pose = demonstration.pose(step, object)) {
        Marker end = newMarker(header, ns, id++, Marker::SPHERE);
        end.pose.position = pointOf(*pose);
        end.scale.x = end.scale.y = end.scale.z = 0.03;
        end.color = color;
        markers.markers.push_back(end);
        Marker label = newMarker(header, ns, id++, Marker::TEXT_VIEW_FACING);
        label.pose.position = pointOf(*pose);
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
