#include "asr_ism_tree/ros/scene_markers.hpp"

#include <algorithm>
#include <map>

#include "asr_common/ros/marker_style.hpp"
#include "asr_common/ros/object_estimate_message.hpp"

namespace asr_ism_tree::ros_interface {
namespace {

using namespace asr_common::ros_interface;
using visualization_msgs::Marker;

constexpr double kSphereHeight = 0.4;  // metres above the instance's pose
constexpr double kObjectBox = 0.06;

// Distinct colours for the ISMs of a tree, root first.
std_msgs::ColorRGBA ismColor(std::size_t ism) {
  static const double palette[][3] = {{0.12, 0.47, 0.71}, {1.0, 0.5, 0.05},   {0.17, 0.63, 0.17},
                                      {0.84, 0.15, 0.16}, {0.58, 0.40, 0.74}, {0.55, 0.34, 0.29},
                                      {0.89, 0.47, 0.76}, {0.5, 0.5, 0.5},    {0.74, 0.74, 0.13},
                                      {0.09, 0.75, 0.81}};
  const auto& rgb = palette[ism % (sizeof palette / sizeof palette[0])];
  return rgbaColor(rgb[0], rgb[1], rgb[2]);
}

// The confidence sphere above an instance, its label and the stem down to its pose.
void addInstanceSign(const SceneInstance& instance, const std_msgs::Header& header, int& id,
                     visualization_msgs::MarkerArray& markers) {
  const Eigen::Vector3d above = instance.pose.position + Eigen::Vector3d(0, 0, kSphereHeight);
  Marker sphere = newMarker(header, instance.scene, id++, Marker::SPHERE);
  sphere.pose.position = pointOf(above);
  sphere.scale.x = sphere.scale.y = sphere.scale.z = 0.1;
  sphere.color = confidenceColor(instance.confidence);
  markers.markers.push_back(sphere);

  Marker text = newMarker(header, instance.scene, id++, Marker::TEXT_VIEW_FACING);
  text.pose.position = pointOf(above + Eigen::Vector3d(0, 0, 0.1));
  text.scale.z = 0.06;
  text.color = rgbaColor(1, 1, 1);
  char label[128];
  // ">=": a search ran out, so the exhaustive best may be higher.
  std::snprintf(label, sizeof label, "%s %s%.2f (objects %.2f)", instance.scene.c_str(),
                instance.search_complete ? "" : ">=", instance.confidence,
                instance.object_confidence);
  text.text = label;
  markers.markers.push_back(text);
}

void addStem(const SceneInstance& instance, const std_msgs::Header& header, int& id,
             visualization_msgs::MarkerArray& markers) {
  const Eigen::Vector3d above = instance.pose.position + Eigen::Vector3d(0, 0, kSphereHeight);
  Marker stem = newMarker(header, instance.scene, id++, Marker::LINE_LIST);
  stem.scale.x = 0.005;
  stem.color = confidenceColor(instance.confidence);
  stem.points = {pointOf(instance.pose.position), pointOf(above)};
  markers.markers.push_back(stem);
}

// A box per object found, coloured by its similarity; where each is, for the relation lines.
std::map<ObjectKey, Eigen::Vector3d> addObjectBoxes(const SceneInstance& instance,
                                                    const std_msgs::Header& header, int& id,
                                                    visualization_msgs::MarkerArray& markers) {
  std::map<ObjectKey, Eigen::Vector3d> object_positions;
  for (const InstanceObject& object : instance.objects) {
    if (object.similarity <= 0.0)
      continue;
    object_positions[object.key] = object.pose.position;
    Marker box = newMarker(header, instance.scene, id++, Marker::CUBE);
    box.pose = toPoseMessage(object.pose);
    box.scale.x = box.scale.y = box.scale.z = kObjectBox;
    box.color = confidenceColor(object.similarity);
    box.color.a = 0.8f;
    markers.markers.push_back(box);
  }
  return object_positions;
}

// Lines from the reference of ISM `i` to each member found: an object, or a recognised child
// ISM's reference.
Marker ismRelationLines(const SceneInstance& instance, const IsmTree& tree, std::size_t i,
                        const std::map<ObjectKey, Eigen::Vector3d>& object_positions,
                        const std_msgs::Header& header, int id) {
  const InstanceIsm& ism = instance.isms[i];
  Marker lines = newMarker(header, instance.scene, id, Marker::LINE_LIST);
  lines.scale.x = 0.01;
  lines.color = ismColor(i);
  for (const asr_ism::IsmMember& member : tree.isms[i].members) {
    Eigen::Vector3d target;
    if (member.isPlaceholder()) {
      const InstanceIsm& child = instance.isms.at(member.child_ism);
      if (!child.recognized)
        continue;
      target = child.reference_pose.position;
    } else {
      const auto found = object_positions.find(member.object);
      if (found == object_positions.end())
        continue;
      target = found->second;
    }
    if ((target - ism.reference_pose.position).norm() < 1e-9)
      continue;
    lines.points.push_back(pointOf(ism.reference_pose.position));
    lines.points.push_back(pointOf(target));
  }
  return lines;
}

}  // namespace

std_msgs::ColorRGBA confidenceColor(double confidence) {
  const double c = std::clamp(confidence, 0.0, 1.0);
  return rgbaColor(std::min(1.0, 2.0 * (1.0 - c)), std::min(1.0, 2.0 * c), 0.0);
}

visualization_msgs::MarkerArray sceneInstanceMarkers(const std::vector<SceneInstance>& instances,
                                                     const SceneModels& models,
                                                     const std_msgs::Header& header) {
  visualization_msgs::MarkerArray markers;
  markers.markers.push_back(deleteAllMarker(header));
  std::map<std::string, int> next_id;  // per namespace (scene)
  for (const SceneInstance& instance : instances) {
    int& id = next_id[instance.scene];
    addInstanceSign(instance, header, id, markers);
    const auto object_positions = addObjectBoxes(instance, header, id, markers);
    addStem(instance, header, id, markers);
    if (!models.has(instance.scene))
      continue;
    const IsmTree& tree = models.tree(instance.scene);
    for (std::size_t i = 0; i < tree.isms.size() && i < instance.isms.size(); ++i) {
      if (!instance.isms[i].recognized)
        continue;
      Marker lines = ismRelationLines(instance, tree, i, object_positions, header, id++);
      if (!lines.points.empty())
        markers.markers.push_back(lines);
    }
  }
  return markers;
}

}  // namespace asr_ism_tree::ros_interface
