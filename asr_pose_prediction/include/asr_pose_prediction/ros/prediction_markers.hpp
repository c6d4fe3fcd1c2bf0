#pragma once

#include <asr_msgs/PredictedPoseCloud.h>
#include <visualization_msgs/MarkerArray.h>

#include <string>
#include <vector>

namespace asr_pose_prediction::ros_interface {

/// How predicted poses are drawn.
struct PredictionMarkerStyle {
  double arrow_length = 0.05;  // metres; an arrow along each pose's x axis
  double alpha = 0.6;
};

/// rviz markers for pose clouds: a DELETEALL first (stale clouds vanish), then per cloud and
/// object one ARROW per predicted pose, coloured per object type (the same colour for a type in
/// every scene and run), and a text with the object's name above the cloud's mean position.
/// Namespaces "<scene>/<type>:<id>", so rviz can show or hide them per scene and object.
visualization_msgs::MarkerArray predictionMarkers(
    const std::vector<asr_msgs::PredictedPoseCloud>& clouds, const PredictionMarkerStyle& style);

/// A colour of full saturation per object type, fixed by the type's name alone.
std_msgs::ColorRGBA objectTypeColor(const std::string& type, double alpha);

}  // namespace asr_pose_prediction::ros_interface
