#pragma once

#include <ros/node_handle.h>

#include <string>
#include <vector>

#include "asr_common/input_error.hpp"

// Private parameters of the suite's nodes, read once at start-up and checked: a missing required
// parameter or a value of the wrong type or range is an InputError naming the parameter, which
// the node reports before it exits non-zero.
namespace asr_common::ros_interface {

/// "~name" as the user writes it, resolved in `node` for messages.
inline std::string parameterName(const ros::NodeHandle& node, const std::string& name) {
  return node.resolveName(name);
}

/// A required parameter; throws InputError if it is missing or of another type.
template <typename T>
T requiredParameter(const ros::NodeHandle& node, const std::string& name) {
  T value;
  if (!node.hasParam(name))
    throw InputError("parameter " + parameterName(node, name) + " is required but not set");
  if (!node.getParam(name, value))
    throw InputError("parameter " + parameterName(node, name) + " has the wrong type");
  return value;
}

/// An optional parameter with a default; throws InputError if it is set with another type.
template <typename T>
T optionalParameter(const ros::NodeHandle& node, const std::string& name, const T& fallback) {
  if (!node.hasParam(name))
    return fallback;
  T value;
  if (!node.getParam(name, value))
    throw InputError("parameter " + parameterName(node, name) + " has the wrong type");
  return value;
}

/// A list of strings that may also be given as one string (a one-element list), as on a command
/// line (`_model_files:=a.sqlite`), where roscpp takes no lists. Empty if not set.
inline std::vector<std::string> stringListParameter(const ros::NodeHandle& node,
                                                    const std::string& name) {
  std::vector<std::string> list;
  if (!node.hasParam(name) || node.getParam(name, list))
    return list;
  std::string single;
  if (node.getParam(name, single))
    return {single};
  throw InputError("parameter " + parameterName(node, name) +
                   " must be a list of strings or a string");
}

/// Throws InputError naming the parameter unless `valid`; `expected` says what would be.
inline void checkParameter(const ros::NodeHandle& node, const std::string& name, bool valid,
                           const std::string& expected) {
  if (!valid)
    throw InputError("parameter " + parameterName(node, name) + " must be " + expected);
}

/// ~fixed_frame (default map), not empty.
inline std::string fixedFrameParameter(const ros::NodeHandle& node) {
  const auto frame = optionalParameter<std::string>(node, "fixed_frame", "map");
  checkParameter(node, "fixed_frame", !frame.empty(), "a frame name, not empty");
  return frame;
}

}  // namespace asr_common::ros_interface
