#pragma once

#include <geometry_msgs/Point.h>
#include <std_msgs/ColorRGBA.h>
#include <std_msgs/Header.h>
#include <visualization_msgs/Marker.h>
#include <Eigen/Core>

#include <string>

// What the suite's rviz markers share: colours, points and new markers.
namespace asr_common::ros_interface {

/// A colour of full saturation at `hue` in [0, 1) around the colour wheel.
std_msgs::ColorRGBA hueColor(double hue, double alpha = 1.0);

std_msgs::ColorRGBA rgbaColor(double r, double g, double b, double a = 1.0);

geometry_msgs::Point pointOf(const Eigen::Vector3d& position);

/// An ADD marker of `type` with identity pose in `header`'s frame.
visualization_msgs::Marker newMarker(const std_msgs::Header& header, const std::string& ns, int id,
                                     int type);

/// The DELETEALL marker that opens every marker array of the suite, so that what is gone
/// vanishes from rviz.
visualization_msgs::Marker deleteAllMarker(const std_msgs::Header& header);

}  // namespace asr_common::ros_interface
