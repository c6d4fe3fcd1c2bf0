// The replay_demonstration node: see asr_ism/ros/replay_node.hpp.
#include <ros/ros.h>

#include <iostream>

#include "asr_ism/input_error.hpp"
#include "asr_ism/ros/replay_node.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "replay_demonstration");
  try {
    asr_ism::ros_interface::ReplayNode node(ros::NodeHandle(), ros::NodeHandle("~"));
    node.run();
    // Give subscribers the last set before the connections close.
    ros::WallDuration(0.5).sleep();
  } catch (const asr_ism::InputError& error) {
    // std::cerr too: the node may fail before its ROS logging is connected.
    ROS_FATAL("replay_demonstration: %s", error.what());
    std::cerr << "replay_demonstration: " << error.what() << std::endl;
    return 1;
  }
  return 0;
}
