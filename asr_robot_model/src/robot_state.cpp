#include "asr_robot_model/robot_state.hpp"

#include <cmath>

#include "asr_common/input_error.hpp"

namespace asr_robot_model {

double wrapAngle(double angle) {
  double wrapped = std::remainder(angle, 2.0 * M_PI);
  if (wrapped <= -M_PI)
    wrapped += 2.0 * M_PI;
  return wrapped;
}

void checkFinite(const RobotState& state, const std::string& what) {
  const std::pair<const char*, double> fields[] = {
      {"x", state.x}, {"y", state.y}, {"yaw", state.yaw}, {"pan", state.pan}, {"tilt", state.tilt}};
  for (const auto& [name, value] : fields) {
    if (!std::isfinite(value))
      throw asr_common::InputError(what + ": " + name + " is not finite (NaN or infinity)");
  }
}

}  // namespace asr_robot_model
