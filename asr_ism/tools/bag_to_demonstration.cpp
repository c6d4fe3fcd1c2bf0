// `bag_to_demonstration`: converts a rosbag of object estimates into a demonstration file that
// the recorder, the trainer and `asr ism learn` read. See asr_ism/ros/bag_conversion.hpp.
#include <iostream>
#include <string>
#include <vector>

#include "asr_common/cli/command_line.hpp"
#include "asr_common/cli/command_main.hpp"
#include "asr_ism/ros/bag_conversion.hpp"

namespace {

const char* const kUsage =
    "usage: bag_to_demonstration --bag BAG --topic TOPIC --demonstration OUT --scene NAME\n"
    "                            [--fixed-frame FRAME]\n"
    "  writes every asr_msgs/ObjectEstimateList message on TOPIC as one recorded set of scene\n"
    "  NAME into OUT (original ASR schema; created or appended to), estimates transformed into\n"
    "  FRAME (default map) with the bag's /tf and /tf_static.\n";

int convert(const std::vector<std::string>& arguments) {
  const asr_common::cli::CommandLine options(
      arguments, {"bag", "topic", "demonstration", "scene", "fixed-frame"}, {});
  const std::string topic = options.required("topic");
  const std::string demonstration = options.required("demonstration");
  const std::string scene = options.required("scene");
  const auto conversion = asr_ism::ros_interface::convertBagToDemonstration(
      options.required("bag"), topic, demonstration, scene, options.optional("fixed-frame", "map"));
  std::cout << "wrote " << conversion.configurations << " sets (" << conversion.estimates
            << " estimates) of scene '" << scene << "' from " << conversion.messages
            << " messages on " << topic << " into " << demonstration << "; " << conversion.rejected
            << " estimates rejected";
  for (const auto& [reason, count] : conversion.rejected_by_reason)
    std::cout << " (" << count << " " << reason << ")";
  std::cout << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return asr_common::cli::runToolMain("bag_to_demonstration", kUsage, convert, argc, argv);
}
