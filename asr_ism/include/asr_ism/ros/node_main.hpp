#pragma once

#include <ros/ros.h>

#include <iostream>
#include <string>

#include "asr_ism/input_error.hpp"

namespace asr_ism::ros_interface {

/// The main() of a node of the suite: ros::init, construct `Node` from the public and private
/// node handles (which reads and checks its parameters), spin with `threads` threads until
/// shutdown. Bad parameters or files end the node with exit code 1 and a message naming them,
/// on the log and on stderr (the log may not be connected yet).
template <typename Node>
int runNode(int argc, char** argv, const std::string& name, unsigned threads = 1) {
  ros::init(argc, argv, name);
  try {
    Node node(ros::NodeHandle(), ros::NodeHandle("~"));
    if (threads <= 1) {
      ros::spin();
    } else {
      ros::AsyncSpinner spinner(threads);
      spinner.start();
      ros::waitForShutdown();
    }
  } catch (const InputError& error) {
    ROS_FATAL("%s: %s", name.c_str(), error.what());
    std::cerr << name << ": " << error.what() << std::endl;
    return 1;
  }
  return 0;
}

}  // namespace asr_ism::ros_interface
