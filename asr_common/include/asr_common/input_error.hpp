#pragma once

#include <stdexcept>
#include <string>

namespace asr_common {

/// Thrown for anything a user supplied that cannot be used: a missing or malformed file, an
/// unknown scene, a NaN pose, a zero quaternion. The message names the offending input.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace asr_common
