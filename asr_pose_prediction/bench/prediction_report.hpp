#pragma once

#include <iosfwd>
#include <nlohmann/json.hpp>
#include <vector>

#include "accuracy_benchmark.hpp"
#include "runtime_benchmark.hpp"

namespace asr_pose_prediction::bench {

/// Human-readable tables, with a note on how each figure was measured.
void printKitchenRuntimeTable(std::ostream& out, const std::vector<RuntimeRow>& rows,
                              const PredictionBenchmarkSettings& settings);
void printSyntheticRuntimeTable(std::ostream& out, const std::vector<RuntimeRow>& rows,
                                const PredictionBenchmarkSettings& settings);
/// Per scene and topology, then the combined rows.
void printAccuracyTable(std::ostream& out, const std::vector<AccuracyRow>& rows,
                        const std::vector<AccuracyRow>& combined,
                        const PredictionBenchmarkSettings& settings);

/// One JSON object per row: scene, topology, objects, steps, isms, height, longest_path, votes,
/// instances, samples, median_ms, max_ms.
nlohmann::ordered_json runtimeRowsToJson(const std::vector<RuntimeRow>& rows);
/// One JSON object per row: scene, topology, held_out, sets, cases, no_instance, and for distance_m,
/// angle_at_nearest_deg and smallest_angle_deg an object {median, p90, max} (null for infinity).
nlohmann::ordered_json accuracyRowsToJson(const std::vector<AccuracyRow>& rows);

}  // namespace asr_pose_prediction::bench
