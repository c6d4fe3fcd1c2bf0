// The replay_demonstration node: see asr_ism/ros/replay_node.hpp.
#include <ros/ros.h>

#include "asr_common/ros/node_main.hpp"
#include "asr_ism/ros/replay_node.hpp"

int main(int argc, char** argv) {
  return asr_common::ros_interface::runNodeMain(argc, argv, "replay_demonstration", [] {
    asr_ism::ros_interface::ReplayNode node(ros::NodeHandle(), ros::NodeHandle("~"));
    node.run();
    // Give subscribers the last set before the connections close.
    ros::WallDuration(0.5).sleep();
  });
}
