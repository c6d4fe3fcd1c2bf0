#pragma once

#include <string>
#include <vector>

#include "asr_common/cli/targets.hpp"
#include "clutter_benchmark.hpp"
#include "recognition_benchmark.hpp"
#include "synthetic_benchmark.hpp"

namespace asr_ism_tree::bench {

/// The suite's targets for the rows at hand; targets whose rows were not measured (scenes
/// skipped, --no-synthetic) are left out.
std::vector<asr_common::cli::Target> checkTargets(
    const std::vector<SceneRow>& scenes, const std::vector<SyntheticRow>& synthetic,
    const std::vector<ClutterRow>& clutter = {},
    const std::vector<ClutterRow>& jittered_clutter = {});

}  // namespace asr_ism_tree::bench
