#pragma once

#include <asr_msgs/RobotState.h>
#include <image_transport/image_transport.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>

#include <memory>
#include <optional>

#include "asr_robot_model/ros/simulation_setup.hpp"
#include "asr_robot_model/tag_camera_sim.hpp"

// camera_sim: the simulated camera (docs/robot.md). It renders what camera_optical_frame sees
// from the robot's latest state (topic robot_state, from robot_driver) in the world, with the
// tags of ~tag_map on its objects, and publishes it as camera/image_raw (mono8) with
// camera/camera_info, stamped with the current ROS time. A camera streams, so frames go out at
// ~rate per second of wall time even while the simulated clock stands still between motions;
// the image depends only on the state, the stamp and ~seed (a frame at the same state and
// simulated time is the same image), so a simulated run stays repeatable.
namespace asr_robot_model::ros_interface {

class CameraSimNode {
 public:
  /// Reads and checks the parameters (SimulationSetup's, ~tag_map, ~width, ~height,
  /// ~horizontal_fov (radians), ~noise_sigma, ~blur_sigma, ~occlusion, ~rate, ~seed); throws
  /// asr_common::InputError naming a bad one.
  CameraSimNode(ros::NodeHandle node, ros::NodeHandle private_node);

 private:
  void onState(const asr_msgs::RobotStateConstPtr& message);
  void publishFrame(const ros::WallTimerEvent& event);

  SimulationSetup setup_;
  std::unique_ptr<TagCameraSim> camera_;
  std::optional<asr_msgs::RobotState> state_;
  unsigned seed_ = 0;
  // The latest frame, sent again while neither the state nor the time changed.
  std::optional<asr_msgs::RobotState> rendered_state_;
  sensor_msgs::Image frame_;

  image_transport::ImageTransport transport_;
  image_transport::CameraPublisher publisher_;
  ros::Subscriber robot_state_;
  ros::WallTimer timer_;
};

}  // namespace asr_robot_model::ros_interface
