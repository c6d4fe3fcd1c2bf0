#pragma once

#include <asr_msgs/DetectObjects.h>
#include <ros/ros.h>

#include <memory>

#include "asr_robot_model/detection_simulator.hpp"
#include "asr_robot_model/ros/simulation_setup.hpp"

// object_detector_sim: the simulated object detector (docs/robot.md). Service detect_objects
// charges ~detection_seconds_per_type of (simulated) time per requested type through
// robot_driver's advance_clock, which also says where the robot is, then detects from that
// camera pose and publishes the estimates on `objects` (asr_msgs/ObjectEstimateList, the topic
// real detectors use). The world is drawn as latched markers on `world_markers`.
namespace asr_robot_model::ros_interface {

class ObjectDetectorSimNode {
 public:
  /// Reads and checks the parameters (SimulationSetup's and ~fovx, ~fovy (radians), ~near, ~far
  /// (metres), ~max_normal_angle (radians), ~position_sigma, ~angle_sigma, ~miss_probability,
  /// ~detection_seconds_per_type, ~seed); throws asr_common::InputError naming a bad one.
  ObjectDetectorSimNode(ros::NodeHandle node, ros::NodeHandle private_node);

 private:
  bool detect(asr_msgs::DetectObjects::Request& request,
              asr_msgs::DetectObjects::Response& response);
  /// The requested types, or every type of the world if none; throws InputError for an empty
  /// type or one the catalogue does not know.
  std::vector<std::string> typesToDetect(const std::vector<std::string>& requested) const;

  SimulationSetup setup_;
  DetectionSettings settings_;
  std::unique_ptr<DetectionSimulator> simulator_;
  ros::ServiceClient advance_clock_;
  ros::Publisher objects_;
  ros::Publisher markers_;
  ros::ServiceServer detect_objects_;
};

}  // namespace asr_robot_model::ros_interface
