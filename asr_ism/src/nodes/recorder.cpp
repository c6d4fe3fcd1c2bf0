// The recorder node: see asr_ism/ros/recorder_node.hpp.
#include "asr_common/ros/node_main.hpp"
#include "asr_ism/ros/recorder_node.hpp"

int main(int argc, char** argv) {
  // One thread: configurations are written in the order they arrive.
  return asr_common::ros_interface::runNode<asr_ism::ros_interface::RecorderNode>(argc, argv,
                                                                                  "recorder");
}
