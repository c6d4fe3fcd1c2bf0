#pragma once

#include <iosfwd>
#include <nlohmann/json.hpp>
#include <vector>

#include "benchmark_settings.hpp"
#include "recognition_benchmark.hpp"
#include "synthetic_benchmark.hpp"

namespace asr_ism_tree::bench {

/// Human-readable tables, with a note on how each figure was measured.
void printSceneTable(std::ostream& out, const std::vector<SceneRow>& rows,
                     const BenchmarkSettings& settings);
void printSyntheticTable(std::ostream& out, const std::vector<SyntheticRow>& rows,
                         const BenchmarkSettings& settings);

/// One JSON object per row with exactly the keys scene, topology, objects, sets, isms, height,
/// votes, learn_ms, recog_median_ms, recog_max_ms, recognised_fraction, missing_one_confidence.
nlohmann::ordered_json sceneRowsToJson(const std::vector<SceneRow>& rows);
/// One JSON object per row: objects, steps, isms, height, votes, learn_ms, configurations,
/// recog_median_ms, recog_max_ms, recognised_fraction.
nlohmann::ordered_json syntheticRowsToJson(const std::vector<SyntheticRow>& rows);

}  // namespace asr_ism_tree::bench
