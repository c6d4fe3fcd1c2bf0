#include "nbv_json.hpp"

#include <cmath>
#include <sstream>
#include <vector>

namespace asr_nbv::tools {

nlohmann::ordered_json poseJson(const asr_common::Pose& pose) {
  nlohmann::ordered_json json;
  json["position"] = {{"x", pose.position.x()}, {"y", pose.position.y()}, {"z", pose.position.z()}};
  json["orientation"] = {{"x", pose.orientation.x()},
                         {"y", pose.orientation.y()},
                         {"z", pose.orientation.z()},
                         {"w", pose.orientation.w()}};
  return json;
}

nlohmann::ordered_json plannedViewJson(const PlannedView& view) {
  nlohmann::ordered_json json;
  json["found"] = view.found;
  if (view.found) {
    const asr_robot_model::RobotState& s = view.state;
    json["view"] = {
        {"camera", poseJson(view.camera)},
        {"state", {{"x", s.x}, {"y", s.y}, {"yaw", s.yaw}, {"pan", s.pan}, {"tilt", s.tilt}}},
        {"types", view.types}};
  }
  json["utility"] = view.utility;
  json["utility_max"] = view.utility_max;
  json["rating"] = view.rating;
  json["costs"] = {{"base", view.costs.base},
                   {"rotation", view.costs.rotation},
                   {"pan_tilt", view.costs.pan_tilt},
                   {"recognition", view.costs.recognition},
                   {"motion_seconds", view.motion_seconds}};
  json["candidates_rated"] = view.candidates_rated;
  json["steps"] = view.steps;
  return json;
}

asr_robot_model::RobotState stateOption(const asr_common::cli::CommandLine& options,
                                        const std::string& name,
                                        const asr_robot_model::RobotState& fallback) {
  if (!options.has(name))
    return fallback;
  std::istringstream text(options.required(name));
  std::vector<double> values;
  std::string word;
  while (text >> word) {
    std::size_t used = 0;
    double value = NAN;
    try {
      value = std::stod(word, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != word.size() || !std::isfinite(value))
      throw asr_common::cli::UsageError{"--" + name + ": '" + word + "' is not a finite number"};
    values.push_back(value);
  }
  if (values.size() != 5)
    throw asr_common::cli::UsageError{"--" + name + " takes \"x y yaw pan tilt\" (5 numbers)"};
  return {values[0], values[1], values[2], values[3], values[4]};
}

}  // namespace asr_nbv::tools
