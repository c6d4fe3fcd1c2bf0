#include "asr_robot_model/ros/object_detector_sim_node.hpp"

#include <asr_msgs/AdvanceClock.h>
#include <asr_msgs/ObjectEstimateList.h>

#include <set>

#include "asr_common/input_error.hpp"
#include "asr_common/ros/node_parameters.hpp"
#include "asr_common/ros/object_estimate_message.hpp"
#include "asr_common/ros/queue_sizes.hpp"
#include "asr_robot_model/forward_kinematics.hpp"
#include "asr_robot_model/ros/robot_state_message.hpp"
#include "asr_robot_model/ros/world_markers.hpp"

namespace asr_robot_model::ros_interface {
namespace {

using namespace asr_common::ros_interface;

DetectionSettings detectionParameters(const ros::NodeHandle& node) {
  const DetectionSettings defaults;
  const Frustum& view = defaults.frustum;
  DetectionSettings settings;
  settings.frustum = Frustum(numberParameter(node, "fovx", view.fovx(), 1e-3, M_PI - 1e-3),
                             numberParameter(node, "fovy", view.fovy(), 1e-3, M_PI - 1e-3),
                             numberParameter(node, "near", view.near(), 0.0, 100.0),
                             numberParameter(node, "far", view.far(), 1e-3, 100.0));
  settings.max_normal_angle =
      numberParameter(node, "max_normal_angle", defaults.max_normal_angle, 0.0, M_PI);
  settings.position_sigma = numberParameter(node, "position_sigma", 0.0, 0.0, 10.0);
  settings.angle_sigma = numberParameter(node, "angle_sigma", 0.0, 0.0, M_PI);
  settings.miss_probability = numberParameter(node, "miss_probability", 0.0, 0.0, 1.0);
  settings.seconds_per_type =
      numberParameter(node, "detection_seconds_per_type", defaults.seconds_per_type, 0.0, 3600.0);
  return settings;
}

}  // namespace

ObjectDetectorSimNode::ObjectDetectorSimNode(ros::NodeHandle node, ros::NodeHandle private_node)
    : setup_(loadSimulationSetup(private_node)), settings_(detectionParameters(private_node)) {
  const auto seed =
      static_cast<unsigned>(integerParameter(private_node, "seed", 1, 0, 4294967295LL));
  simulator_ = std::make_unique<DetectionSimulator>(setup_.world, *setup_.map, settings_, seed);
  advance_clock_ = node.serviceClient<asr_msgs::AdvanceClock>("advance_clock", true);
  objects_ = node.advertise<asr_msgs::ObjectEstimateList>("objects", kResultQueue);
  markers_ = node.advertise<visualization_msgs::MarkerArray>("world_markers", kLatchedQueue, true);
  std_msgs::Header header;
  header.frame_id = setup_.world.frame;
  markers_.publish(
      worldMarkers(setup_.world, *setup_.map, settings_.frustum, header, kCameraFrame));
  detect_objects_ = node.advertiseService("detect_objects", &ObjectDetectorSimNode::detect, this);
}

std::vector<std::string> ObjectDetectorSimNode::typesToDetect(
    const std::vector<std::string>& requested) const {
  if (requested.empty()) {
    std::set<std::string> all;
    for (const WorldObject& object : setup_.world.objects)
      all.insert(object.key.type);
    return {all.begin(), all.end()};
  }
  for (const std::string& type : requested) {
    if (type.empty())
      throw asr_common::InputError("detect_objects: a requested type is empty");
    const bool in_world = std::any_of(setup_.world.objects.begin(), setup_.world.objects.end(),
                                      [&](const WorldObject& o) { return o.key.type == type; });
    if (!in_world && !setup_.catalogue.count(type))
      throw asr_common::InputError("detect_objects: type '" + type +
                                   "' is neither in the world nor in the object catalogue");
  }
  return requested;
}

bool ObjectDetectorSimNode::detect(asr_msgs::DetectObjects::Request& request,
                                   asr_msgs::DetectObjects::Response& response) {
  std::vector<std::string> types;
  try {
    types = typesToDetect(request.types);
  } catch (const asr_common::InputError& error) {
    ROS_WARN("object_detector_sim: %s", error.what());
    return false;
  }
  asr_msgs::AdvanceClock wait;
  wait.request.seconds = settings_.seconds_per_type * static_cast<double>(types.size());
  if (!advance_clock_.call(wait)) {
    // A persistent connection may have gone with a restarted driver: one fresh try.
    advance_clock_ = ros::NodeHandle().serviceClient<asr_msgs::AdvanceClock>("advance_clock", true);
    if (!advance_clock_.call(wait)) {
      ROS_ERROR("object_detector_sim: robot_driver's advance_clock did not answer");
      return false;
    }
  }
  const Detections detections =
      simulator_->detect(cameraPose(setup_.robot, fromStateMessage(wait.response.state)), types);
  std_msgs::Header header;
  header.stamp = wait.response.now;
  header.frame_id = setup_.world.frame;
  response.estimates.header = header;
  for (const asr_common::ObjectEstimate& estimate : detections.detected)
    response.estimates.objects.push_back(toEstimateMessage(estimate, header));
  response.seconds = wait.request.seconds;
  objects_.publish(response.estimates);
  return true;
}

}  // namespace asr_robot_model::ros_interface
