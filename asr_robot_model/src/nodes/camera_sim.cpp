// The simulated camera: see asr_robot_model/ros/camera_sim_node.hpp.
#include "asr_common/ros/node_main.hpp"
#include "asr_robot_model/ros/camera_sim_node.hpp"

int main(int argc, char** argv) {
  return asr_common::ros_interface::runNode<asr_robot_model::ros_interface::CameraSimNode>(
      argc, argv, "camera_sim");
}
