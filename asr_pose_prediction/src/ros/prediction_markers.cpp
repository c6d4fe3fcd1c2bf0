#include "asr_pose_prediction/ros/prediction_markers.hpp"

#include <cmath>
#include <cstdint>
#include <map>

#include "asr_common/ros/marker_style.hpp"

namespace asr_pose_prediction::ros_interface {

using asr_common::ros_interface::deleteAllMarker;
using asr_common::ros_interface::newMarker;

std_msgs::ColorRGBA objectTypeColor(const std::string& type, double alpha) {
  // FNV-1a: a hash that is the same on every platform and run (std::hash is not).
  std::uint32_t hash = 2166136261u;
  for (unsigned char c : type)
    hash = (hash ^ c) * 16777619u;
  return asr_common::ros_interface::hueColor((hash % 360u) / 360.0, alpha);
}

visualization_msgs::MarkerArray predictionMarkers(
    const std::vector<asr_msgs::PredictedPoseCloud>& clouds, const PredictionMarkerStyle& style) {
  visualization_msgs::MarkerArray markers;
  markers.markers.push_back(
      deleteAllMarker(clouds.empty() ? std_msgs::Header() : clouds.front().header));

  // Clouds of several instances may hold the same object: ids count on per namespace.
  std::map<std::string, int> next_id;
  for (const asr_msgs::PredictedPoseCloud& cloud : clouds) {
    for (const asr_msgs::PredictedObjectPoses& object : cloud.objects) {
      const std::string name =
          object.instance_id.empty() ? object.type : object.type + ":" + object.instance_id;
      const std::string ns = cloud.scene + "/" + name;
      const std_msgs::ColorRGBA color = objectTypeColor(object.type, style.alpha);
      int& id = next_id[ns];
      geometry_msgs::Point mean;
      for (const geometry_msgs::Pose& pose : object.poses) {
        visualization_msgs::Marker arrow =
            newMarker(cloud.header, ns, id++, visualization_msgs::Marker::ARROW);
        arrow.pose = pose;
        arrow.scale.x = style.arrow_length;
        arrow.scale.y = style.arrow_length * 0.15;
        arrow.scale.z = style.arrow_length * 0.15;
        arrow.color = color;
        markers.markers.push_back(arrow);
        mean.x += pose.position.x / object.poses.size();
        mean.y += pose.position.y / object.poses.size();
        mean.z += pose.position.z / object.poses.size();
      }
      if (object.poses.empty())
        continue;
      visualization_msgs::Marker label =
          newMarker(cloud.header, ns, id++, visualization_msgs::Marker::TEXT_VIEW_FACING);
      label.pose.position = mean;
      label.pose.position.z += 3 * style.arrow_length;
      label.scale.z = 0.6 * style.arrow_length;
      label.color = color;
      label.color.a = 1.0;
      label.text = name + " (" + cloud.scene + ")";
      markers.markers.push_back(label);
    }
  }
  return markers;
}

}  // namespace asr_pose_prediction::ros_interface
