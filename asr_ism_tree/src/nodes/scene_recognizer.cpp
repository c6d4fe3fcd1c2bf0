// The scene recogniser node: see asr_ism_tree/ros/scene_recognizer_node.hpp.
#include <ros/ros.h>

#include <iostream>

#include "asr_ism/input_error.hpp"
#include "asr_ism_tree/ros/scene_recognizer_node.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "scene_recognizer");
  try {
    asr_ism_tree::ros_interface::SceneRecognizerNode node(ros::NodeHandle(), ros::NodeHandle("~"));
    ros::AsyncSpinner spinner(2);  // a service call does not hold up the continuous mode
    spinner.start();
    ros::waitForShutdown();
  } catch (const asr_ism::InputError& error) {
    // std::cerr too: the node may fail before its ROS logging is connected.
    ROS_FATAL("scene_recognizer: %s", error.what());
    std::cerr << "scene_recognizer: " << error.what() << std::endl;
    return 1;
  }
  return 0;
}
