// The pose predictor node: see asr_pose_prediction/ros/pose_predictor_node.hpp.
#include <ros/ros.h>

#include <iostream>

#include "asr_ism/input_error.hpp"
#include "asr_pose_prediction/ros/pose_predictor_node.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "pose_predictor");
  try {
    asr_pose_prediction::ros_interface::PosePredictorNode node(ros::NodeHandle(),
                                                               ros::NodeHandle("~"));
    ros::AsyncSpinner spinner(2);
    spinner.start();
    ros::waitForShutdown();
  } catch (const asr_ism::InputError& error) {
    // std::cerr too: the node may fail before its ROS logging is connected.
    ROS_FATAL("pose_predictor: %s", error.what());
    std::cerr << "pose_predictor: " << error.what() << std::endl;
    return 1;
  }
  return 0;
}
