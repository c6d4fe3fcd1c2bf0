// The simulated object detector: see asr_robot_model/ros/object_detector_sim_node.hpp.
#include "asr_common/ros/node_main.hpp"
#include "asr_robot_model/ros/object_detector_sim_node.hpp"

int main(int argc, char** argv) {
  return asr_common::ros_interface::runNode<asr_robot_model::ros_interface::ObjectDetectorSimNode>(
      argc, argv, "object_detector_sim");
}
