#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "accuracy_benchmark.hpp"
#include "asr_common/cli/targets.hpp"
#include "runtime_benchmark.hpp"

namespace asr_pose_prediction::bench {

/// The targets for the rows at hand: runtime of 100 poses of every object at 10 objects x 400
/// steps (complete, and star), and the median leave-one-out distance and angles over all scenes
/// (per topology; for the trees learned from all sets, the measure, and for held-out
/// sets). Targets whose rows were not measured are left out.
std::vector<asr_common::cli::Target> checkPredictionTargets(
    const std::vector<RuntimeRow>& synthetic, const std::vector<AccuracyRow>& combined);

nlohmann::ordered_json targetsToJson(const std::vector<asr_common::cli::Target>& targets);

}  // namespace asr_pose_prediction::bench
