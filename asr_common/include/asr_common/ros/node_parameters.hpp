#pragma once

#include <ros/node_handle.h>

#include <cmath>
#include <iomanip>
#include <sstream>
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

/// An optional integer parameter in [min, max] (the one checked integer parameter reading of the
/// suite's nodes). Throws InputError naming the parameter and the range if it is not an integer
/// or out of range: refused, never truncated or wrapped. roscpp stores integers beyond 32 bits
/// as doubles (`_seed:=4294967295`), and its getParam(int) would cast those; a double with an
/// integral value counts as that integer here.
inline long long integerParameter(const ros::NodeHandle& node, const std::string& name,
                                  long long fallback, long long min, long long max) {
  if (!node.hasParam(name))
    return fallback;
  const std::string range = "[" + std::to_string(min) + ", " + std::to_string(max) + "]";
  XmlRpc::XmlRpcValue stored;
  node.getParam(name, stored);
  double value = 0.0;
  if (stored.getType() == XmlRpc::XmlRpcValue::TypeInt)
    value = static_cast<int>(stored);
  else if (stored.getType() == XmlRpc::XmlRpcValue::TypeDouble)
    value = static_cast<double>(stored);
  if (!(stored.getType() == XmlRpc::XmlRpcValue::TypeInt ||
        (stored.getType() == XmlRpc::XmlRpcValue::TypeDouble && std::isfinite(value) &&
         value == std::floor(value)))) {
    throw InputError("parameter " + parameterName(node, name) + " must be an integer in " + range);
  }
  // Every long long limit used here is below 2^53, so the comparison in double is exact.
  if (!(value >= static_cast<double>(min) && value <= static_cast<double>(max))) {
    std::ostringstream message;
    message << std::setprecision(17) << "parameter " << parameterName(node, name)
            << " is out of range: " << value << " is not in " << range;
    throw InputError(message.str());
  }
  return static_cast<long long>(value);
}

/// An optional finite number parameter in [min, max]; throws InputError naming the parameter and
/// the range otherwise (an integer given for a number is fine).
inline double numberParameter(const ros::NodeHandle& node, const std::string& name, double fallback,
                              double min, double max) {
  const double value = optionalParameter<double>(node, name, fallback);
  if (!(std::isfinite(value) && value >= min && value <= max)) {
    std::ostringstream message;
    message << "parameter " << parameterName(node, name) << " is out of range: " << value
            << " is not in [" << min << ", " << max << "]";
    throw InputError(message.str());
  }
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
