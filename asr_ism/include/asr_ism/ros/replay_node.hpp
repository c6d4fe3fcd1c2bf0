#pragma once

#include <ros/ros.h>
#include <rosbag/bag.h>

#include <memory>

#include <string>
#include <vector>

#include "asr_ism/demonstration.hpp"

namespace asr_ism::ros_interface {

/// The replay_demonstration node: publishes the recorded sets of one scene of a demonstration
/// file as asr_msgs/ObjectEstimateList on `objects`, one set per 1/rate seconds, in the fixed
/// frame, and the demonstration's trajectories on demonstration_markers (latched). Parameters
/// (private): demonstration_file and scene (required), rate (sets per second, 2), loop (false),
/// fixed_frame (map), wait_for_subscribers (true: start once `objects` has a subscriber, so
/// that no set is lost; not when writing a bag), hide_types (list of object types left out of every set, e.g. to show
/// the pose prediction of objects not seen yet), bag (a rosbag file the published sets are also
/// written to, on /objects; refused if it exists, so no recording is overwritten; empty: none).
/// Without loop the node ends after the last set, so a launch of it ends by itself.
class ReplayNode {
 public:
  /// Reads and checks the parameters and the file: throws InputError naming them.
  ReplayNode(ros::NodeHandle node, ros::NodeHandle private_node);

  /// Publishes the sets; returns when done (or on shutdown).
  void run();

 private:
  ros::NodeHandle node_;
  Demonstration demonstration_;
  std::string fixed_frame_;
  double rate_ = 2.0;
  bool loop_ = false;
  bool wait_for_subscribers_ = true;
  std::vector<std::string> hide_types_;
  ros::Publisher objects_publisher_;
  ros::Publisher markers_publisher_;
  std::unique_ptr<rosbag::Bag> bag_;
};

}  // namespace asr_ism::ros_interface
