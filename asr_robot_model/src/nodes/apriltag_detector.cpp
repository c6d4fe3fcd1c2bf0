// The AprilTag object detector: see asr_robot_model/ros/apriltag_detector_node.hpp.
#include "asr_common/ros/node_main.hpp"
#include "asr_robot_model/ros/apriltag_detector_node.hpp"

int main(int argc, char** argv) {
  return asr_common::ros_interface::runNode<asr_robot_model::ros_interface::ApriltagDetectorNode>(
      argc, argv, "apriltag_detector", 2);  // images go on while detect_objects waits
}
