// The pose predictor node: see asr_pose_prediction/ros/pose_predictor_node.hpp.
#include "asr_common/ros/node_main.hpp"
#include "asr_pose_prediction/ros/pose_predictor_node.hpp"

int main(int argc, char** argv) {
  return asr_common::ros_interface::runNode<asr_pose_prediction::ros_interface::PosePredictorNode>(
      argc, argv, "pose_predictor", 2);
}
