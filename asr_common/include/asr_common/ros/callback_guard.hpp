#pragma once

#include <ros/console.h>

#include <exception>
#include <string>

#include "asr_common/input_error.hpp"

namespace asr_common::ros_interface {

/// Runs the body of a topic or timer callback so that no exception leaves it: roscpp turns a
/// service's exception into a failed call, but one from a timer or subscriber ends the process.
/// Bad input (InputError) is logged as a warning, anything else as an error; both name `where`
/// ("node: callback") and are throttled to one line per 5 s per call site. Returns whether the
/// body completed.
template <typename Body>
bool guardCallback(const char* where, Body&& body) noexcept {
  try {
    body();
    return true;
  } catch (const InputError& error) {
    ROS_WARN_THROTTLE(5.0, "%s: skipped: %s", where, error.what());
  } catch (const std::exception& error) {
    ROS_ERROR_THROTTLE(5.0, "%s: skipped after an unexpected error: %s", where, error.what());
  } catch (...) {
    ROS_ERROR_THROTTLE(5.0, "%s: skipped after an unexpected error", where);
  }
  return false;
}

}  // namespace asr_common::ros_interface
