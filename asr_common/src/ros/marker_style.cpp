#include "asr_common/ros/marker_style.hpp"

#include <cmath>

namespace asr_common::ros_interface {

std_msgs::ColorRGBA rgbaColor(double r, double g, double b, double a) {
  std_msgs::ColorRGBA color;
  color.r = static_cast<float>(r);
  color.g = static_cast<float>(g);
  color.b = static_cast<float>(b);
  color.a = static_cast<float>(a);
  return color;
}

std_msgs::ColorRGBA hueColor(double hue, double alpha) {
  const double sectors = 6.0 * (hue - std::floor(hue));  // 0..6
  const double rising = sectors - std::floor(sectors);
  const double r[] = {1, 1 - rising, 0, 0, rising, 1};
  const double g[] = {rising, 1, 1, 1 - rising, 0, 0};
  const double b[] = {0, 0, rising, 1, 1, 1 - rising};
  const int sector = static_cast<int>(sectors) % 6;
  return rgbaColor(r[sector], g[sector], b[sector], alpha);
}

geometry_msgs::Point pointOf(const Eigen::Vector3d& position) {
  geometry_msgs::Point point;
  point.x = position.x();
  point.y = position.y();
  point.z = position.z();
  return point;
}

visualization_msgs::Marker newMarker(const std_msgs::Header& header, const std::string& ns, int id,
                                     int type) {
  visualization_msgs::Marker marker;
  marker.header = header;
  marker.ns = ns;
  marker.id = id;
  marker.type = type;
  marker.action = visualization_msgs::Marker::ADD;
  marker.pose.orientation.w = 1.0;
  return marker;
}

visualization_msgs::Marker deleteAllMarker(const std_msgs::Header& header) {
  visualization_msgs::Marker marker;
  marker.header = header;
  marker.action = visualization_msgs::Marker::DELETEALL;
  return marker;
}

}  // namespace asr_common::ros_interface
