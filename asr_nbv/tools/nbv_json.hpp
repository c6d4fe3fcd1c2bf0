// JSON of the nbv tool: the planned view as `asr nbv --json` prints it.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "asr_common/cli/command_line.hpp"
#include "asr_nbv/next_best_view_planner.hpp"

namespace asr_nbv::tools {

/// {"position": {x, y, z}, "orientation": {x, y, z, w}}
nlohmann::ordered_json poseJson(const asr_common::Pose& pose);

/// {"found", "view": {"camera", "state", "types"}, "utility", "utility_max", "rating",
///  "costs": {"base", "rotation", "pan_tilt", "recognition", "motion_seconds"},
///  "candidates_rated", "steps"}
nlohmann::ordered_json plannedViewJson(const PlannedView& view);

/// The state of option `name` ("x y yaw pan tilt"), `fallback` if it is not given. Throws
/// UsageError naming the option unless it is five finite numbers.
asr_robot_model::RobotState stateOption(const asr_common::cli::CommandLine& options,
                                        const std::string& name,
                                        const asr_robot_model::RobotState& fallback);

}  // namespace asr_nbv::tools
