#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <vector>

#include "asr_ism_tree/scene_instance.hpp"

namespace asr_ism_tree::cli {

/// {"position": {x, y, z}, "orientation": {x, y, z, w}}, geometry_msgs field names.
nlohmann::ordered_json poseToJson(const asr_common::Pose& pose);

/// One instance as in the `recognize --json` output.
nlohmann::ordered_json instanceToJson(const SceneInstance& instance);

/// Instances for a person to read: confidence, pose, each object's ratings, missing objects.
void printInstances(std::ostream& out, const std::vector<SceneInstance>& instances);

}  // namespace asr_ism_tree::cli
