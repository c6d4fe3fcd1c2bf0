#include "asr_nbv/ros/nbv_markers.hpp"

#include <algorithm>

#include "asr_common/ros/marker_style.hpp"
#include "asr_common/ros/object_estimate_message.hpp"
#include "asr_robot_model/ros/world_markers.hpp"

namespace asr_nbv::ros_interface {
namespace {

using namespace asr_common::ros_interface;
using visualization_msgs::Marker;

// Hue from red (0) through yellow to green (1).
std_msgs::ColorRGBA redToGreen(double fraction, double alpha = 1.0) {
  return hueColor(std::clamp(fraction, 0.0, 1.0) / 3.0, alpha);
}

Marker hypothesisMarker(const HypothesisSet& hypotheses, const std_msgs::Header& header) {
  Marker marker = newMarker(header, "hypotheses", 0, Marker::SPHERE_LIST);
  marker.scale.x = marker.scale.y = marker.scale.z = 0.025;
  for (const Hypothesis& hypothesis : hypotheses.hypotheses()) {
    marker.points.push_back(pointOf(hypothesis.box.pose.position));
    marker.colors.push_back(
        redToGreen(static_cast<double>(hypothesis.active_count) / hypothesis.active.size()));
  }
  return marker;
}

void addCandidates(const PlannedView& plan, const std_msgs::Header& header,
                   visualization_msgs::MarkerArray& markers) {
  if (plan.rated.empty())
    return;
  const auto [low, high] = std::minmax_element(
      plan.rated.begin(), plan.rated.end(),
      [](const RatedCandidate& a, const RatedCandidate& b) { return a.rating < b.rating; });
  const double span = high->rating - low->rating;
  Marker cameras = newMarker(header, "candidates", 0, Marker::SPHERE_LIST);
  cameras.scale.x = cameras.scale.y = cameras.scale.z = 0.05;
  Marker axes = newMarker(header, "candidates", 1, Marker::LINE_LIST);
  axes.scale.x = 0.01;
  for (const RatedCandidate& candidate : plan.rated) {
    const std_msgs::ColorRGBA color =
        redToGreen(span > 0.0 ? (candidate.rating - low->rating) / span : 1.0);
    const Eigen::Vector3d& position = candidate.camera.position;
    cameras.points.push_back(pointOf(position));
    cameras.colors.push_back(color);
    axes.points.push_back(pointOf(position));
    axes.points.push_back(
        pointOf(position + 0.3 * (candidate.camera.orientation * Eigen::Vector3d::UnitZ())));
    axes.colors.push_back(color);
    axes.colors.push_back(color);
  }
  markers.markers.push_back(cameras);
  markers.markers.push_back(axes);
}

void addChosenView(const PlannedView& plan, const asr_robot_model::Frustum& frustum,
                   const std_msgs::Header& header, visualization_msgs::MarkerArray& markers) {
  Marker edges = asr_robot_model::ros_interface::frustumMarker(frustum, header, header.frame_id);
  edges.ns = "chosen_view";
  edges.pose = toPoseMessage(plan.camera);
  edges.scale.x = 0.015;
  markers.markers.push_back(edges);
  Marker axis = newMarker(header, "chosen_view", 1, Marker::ARROW);
  axis.points = {pointOf(plan.camera.position),
                 pointOf(plan.camera.position +
                         frustum.near() * (plan.camera.orientation * Eigen::Vector3d::UnitZ()))};
  axis.scale.x = 0.02;
  axis.scale.y = 0.05;
  axis.scale.z = 0.08;
  axis.color = rgbaColor(1.0, 0.8, 0.0, 1.0);
  markers.markers.push_back(axis);
}

}  // namespace

visualization_msgs::MarkerArray nbvMarkers(const HypothesisSet& hypotheses, const PlannedView* plan,
                                           const asr_robot_model::Frustum& frustum,
                                           const std_msgs::Header& header) {
  visualization_msgs::MarkerArray markers;
  markers.markers.push_back(deleteAllMarker(header));
  if (!hypotheses.hypotheses().empty())
    markers.markers.push_back(hypothesisMarker(hypotheses, header));
  if (plan != nullptr) {
    addCandidates(*plan, header, markers);
    if (plan->found)
      addChosenView(*plan, frustum, header, markers);
  }
  return markers;
}

}  // namespace asr_nbv::ros_interface
