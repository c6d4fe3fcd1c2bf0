// The scene recogniser node: see asr_ism_tree/ros/scene_recognizer_node.hpp.
#include "asr_common/ros/node_main.hpp"
#include "asr_ism_tree/ros/scene_recognizer_node.hpp"

int main(int argc, char** argv) {
  // Two threads: a service call does not hold up the continuous mode.
  return asr_common::ros_interface::runNode<asr_ism_tree::ros_interface::SceneRecognizerNode>(
      argc, argv, "scene_recognizer", 2);
}
