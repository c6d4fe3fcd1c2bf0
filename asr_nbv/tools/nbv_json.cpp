#include "nbv_json.hpp"

#include <vector>

#include "asr_ism_tree/cli/scene_instance_output.hpp"

namespace asr_nbv::tools {

nlohmann::ordered_json plannedViewJson(const PlannedView& view) {
  nlohmann::ordered_json json;
  json["found"] = view.found;
  if (view.found) {
    const asr_robot_model::RobotState& s = view.state;
    json["view"] = {
        {"camera", asr_ism_tree::cli::poseToJson(view.camera)},
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
  const std::vector<double> values = options.numbers(name, 5, "x y yaw pan tilt");
  return {values[0], values[1], values[2], values[3], values[4]};
}

}  // namespace asr_nbv::tools
