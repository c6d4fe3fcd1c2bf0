// The simulated robot driver: see asr_robot_model/ros/robot_driver_node.hpp.
#include "asr_common/ros/node_main.hpp"
#include "asr_robot_model/ros/robot_driver_node.hpp"

int main(int argc, char** argv) {
  // Two threads: the actions run in their own, advance_clock waits while a motion runs.
  return asr_common::ros_interface::runNode<asr_robot_model::ros_interface::RobotDriverNode>(
      argc, argv, "robot_driver", 2);
}
