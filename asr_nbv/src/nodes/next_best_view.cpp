// The next-best-view node: see asr_nbv/ros/next_best_view_node.hpp.
#include "asr_common/ros/node_main.hpp"
#include "asr_nbv/ros/next_best_view_node.hpp"

int main(int argc, char** argv) {
  // One thread: the services change and read one set of hypotheses in turn; the planner rates
  // candidates on its own thread pool.
  return asr_common::ros_interface::runNode<asr_nbv::ros_interface::NextBestViewNode>(
      argc, argv, "next_best_view", 1);
}
