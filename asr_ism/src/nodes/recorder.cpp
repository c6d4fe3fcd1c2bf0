// The recorder node: see asr_ism/ros/recorder_node.hpp.
#include <ros/ros.h>

#include <iostream>

#include "asr_ism/input_error.hpp"
#include "asr_ism/ros/recorder_node.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "recorder");
  try {
    asr_ism::ros_interface::RecorderNode node(ros::NodeHandle(), ros::NodeHandle("~"));
    ros::spin();  // one thread: configurations are written in the order they arrive
  } catch (const asr_ism::InputError& error) {
    // std::cerr too: the node may fail before its ROS logging is connected.
    ROS_FATAL("recorder: %s", error.what());
    std::cerr << "recorder: " << error.what() << std::endl;
    return 1;
  }
  return 0;
}
