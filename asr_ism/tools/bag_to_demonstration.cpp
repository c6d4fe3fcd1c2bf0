// `bag_to_demonstration`: converts a rosbag of object estimates into a demonstration file that
// the recorder, the trainer and `asr ism learn` read. See asr_ism/ros/bag_conversion.hpp.
#include <cstring>
#include <iostream>
#include <map>
#include <string>

#include "asr_ism/common_types.hpp"
#include "asr_ism/ros/bag_conversion.hpp"

namespace {

const char* const kUsage =
    "usage: bag_to_demonstration --bag BAG --topic TOPIC --demonstration OUT --scene NAME\n"
    "                            [--fixed-frame FRAME]\n"
    "  writes every asr_msgs/ObjectEstimateList message on TOPIC as one recorded set of scene\n"
    "  NAME into OUT (original ASR schema; created or appended to), estimates transformed into\n"
    "  FRAME (default map) with the bag's /tf and /tf_static.\n";

}  // namespace

int main(int argc, char** argv) {
  std::map<std::string, std::string> options = {{"--fixed-frame", "map"}};
  for (int i = 1; i < argc; ++i) {
    const std::string name = argv[i];
    if (name == "--help" || name == "-h") {
      std::cout << kUsage;
      return 0;
    }
    if ((name != "--bag" && name != "--topic" && name != "--demonstration" && name != "--scene" &&
         name != "--fixed-frame") ||
        i + 1 >= argc) {
      std::cerr << "bag_to_demonstration: unknown option or missing value: " << name << "\n"
                << kUsage;
      return 2;
    }
    options[name] = argv[++i];
  }
  for (const char* required : {"--bag", "--topic", "--demonstration", "--scene"}) {
    if (!options.count(required)) {
      std::cerr << "bag_to_demonstration: " << required << " is required\n" << kUsage;
      return 2;
    }
  }
  try {
    const auto conversion = asr_ism::ros_interface::convertBagToDemonstration(
        options["--bag"], options["--topic"], options["--demonstration"], options["--scene"],
        options["--fixed-frame"]);
    std::cout << "wrote " << conversion.configurations << " sets (" << conversion.estimates
              << " estimates) of scene '" << options["--scene"] << "' from " << conversion.messages
              << " messages on " << options["--topic"] << " into " << options["--demonstration"]
              << "; " << conversion.rejected << " estimates rejected";
    for (const auto& [reason, count] : conversion.rejected_by_reason)
      std::cout << " (" << count << " " << reason << ")";
    std::cout << "\n";
  } catch (const asr_common::InputError& error) {
    std::cerr << "bag_to_demonstration: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
