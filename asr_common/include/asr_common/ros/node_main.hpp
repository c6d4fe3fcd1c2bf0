#pragma once

#include <ros/ros.h>

#include <exception>
#include <string>

namespace asr_common::ros_interface {

/// Says on the log and on stderr (the log may not be connected yet) why node `name` ends.
void reportNodeFailure(const std::string& name, const std::exception& error);

/// The main() of every node of the suite: ros::init as `name`, then `body()`. An exception out
/// of the body (an InputError for bad parameters or files, or any other std::exception) ends the
/// node with exit code 1 and one message naming the node and the cause; otherwise exit code 0.
template <typename Body>
int runNodeMain(int argc, char** argv, const std::string& name, Body&& body) {
  ros::init(argc, argv, name);
  try {
    body();
  } catch (const std::exception& error) {
    reportNodeFailure(name, error);
    return 1;
  }
  return 0;
}

/// runNodeMain for a node that serves until shutdown: constructs `Node` from the public and
/// private node handles (which reads and checks its parameters), then spins with `threads`
/// threads.
template <typename Node>
int runNode(int argc, char** argv, const std::string& name, unsigned threads = 1) {
  return runNodeMain(argc, argv, name, [threads] {
    Node node(ros::NodeHandle(), ros::NodeHandle("~"));
    if (threads <= 1) {
      ros::spin();
      return;
    }
    ros::AsyncSpinner spinner(threads);
    spinner.start();
    ros::waitForShutdown();
  });
}

}  // namespace asr_common::ros_interface
