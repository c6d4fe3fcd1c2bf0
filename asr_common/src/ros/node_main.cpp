#include "asr_common/ros/node_main.hpp"

#include <iostream>

#include "asr_common/input_error.hpp"

namespace asr_common::ros_interface {

void reportNodeFailure(const std::string& name, const std::exception& error) {
  // Bad input is the user's to fix and says so by itself; anything else is named unexpected.
  const bool input_error = dynamic_cast<const InputError*>(&error) != nullptr;
  const std::string message =
      name + ": " + (input_error ? "" : "unexpected error: ") + error.what();
  ROS_FATAL("%s", message.c_str());
  std::cerr << message << std::endl;
}

}  // namespace asr_common::ros_interface
