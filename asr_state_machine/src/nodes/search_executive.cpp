// The search executive node: see asr_state_machine/ros/search_executive_node.hpp.
#include "asr_common/ros/node_main.hpp"
#include "asr_common/ros/node_parameters.hpp"
#include "asr_state_machine/ros/search_executive_node.hpp"

int main(int argc, char** argv) {
  return asr_common::ros_interface::runNodeMain(argc, argv, "search_executive", [] {
    // The search runs on this thread; the spinner serves the robot's state, the action's
    // feedback and the latched topics meanwhile.
    ros::AsyncSpinner spinner(2);
    spinner.start();
    ros::NodeHandle private_node("~");
    const bool exit_when_done =
        asr_common::ros_interface::optionalParameter<bool>(private_node, "exit_when_done", false);
    asr_state_machine::ros_interface::SearchExecutiveNode node(ros::NodeHandle(), private_node);
    try {
      node.run();
    } catch (const asr_common::InputError& error) {
      if (exit_when_done)
        throw;
      ROS_ERROR("search_executive: %s; nothing moved", error.what());
      ros::waitForShutdown();  // the refusal stays on ~result
      return;
    }
    if (!exit_when_done)
      ros::waitForShutdown();
  });
}
