#pragma once

#include <ros/ros.h>

#include <fstream>
#include <memory>
#include <string>

#include "asr_state_machine/search_executive.hpp"
#include "asr_state_machine/search_inputs.hpp"

// search_executive: one active search over the suite's nodes (docs/search.md), the same
// SearchExecutive as `asr search` with the ROS parts (ros_parts.hpp); the direct search and the
// world model run inside the node. Parameters: ~world, ~model_files (list or one file), ~scenes,
// ~required_scenes (dict scene: confidence), ~mode (asr|direct|bbox), ~seed, ~max_sim_minutes
// (60), ~demonstrated, ~catalogue, ~part_timeout (wall seconds a node may take to answer, 60),
// ~samples (60) and ~best_instances (3) of the prediction, ~fixed_frame (map), ~log_file (JSON
// lines), ~result_file (the summary as JSON). Publishes ~state (latched std_msgs/String: the
// executive's state, then the outcome), search_log (asr_msgs/SearchLogEntry per decision),
// ~result (latched std_msgs/String: the summary `asr search --json` prints, or
// {"outcome": "error", "reason"} for bad input) and search_markers (latched).
namespace asr_state_machine::ros_interface {

class SearchExecutiveNode {
 public:
  /// Reads the parameters; nothing is loaded yet.
  SearchExecutiveNode(ros::NodeHandle node, ros::NodeHandle private_node);

  /// Loads and checks the inputs, waits for the nodes, runs the search and publishes its
  /// result. Bad input ends it before anything moves: published as outcome "error", then
  /// rethrown (asr_common::InputError).
  void run();

 private:
  SearchRequest readRequest();
  SearchResult search(const SearchInputs& inputs);
  void publishEntry(const LogEntry& entry, const WorldModel& world, const SearchInputs& inputs);
  void publishResult(const std::string& outcome, const std::string& json);

  ros::NodeHandle node_;
  ros::NodeHandle private_node_;
  ros::Publisher state_;
  ros::Publisher log_;
  ros::Publisher result_;
  ros::Publisher markers_;
  std::string frame_;
  double part_timeout_ = 60.0;
  double startup_timeout_ = 300.0;
  std::size_t samples_ = 60;
  std::size_t best_instances_ = 3;
  std::string result_file_;
  std::ofstream log_file_;
};

}  // namespace asr_state_machine::ros_interface
