#pragma once

#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "accuracy_benchmark.hpp"
#include "runtime_benchmark.hpp"

namespace asr_pose_prediction::bench {

/// One target of the issue and how the measurement compares with it.
struct PredictionTarget {
  std::string target;
  std::string measured;
  bool met = false;
};

/// The targets for the rows at hand: runtime of 100 poses of every object at 10 objects x 400
/// steps (complete, and star), and the median leave-one-out distance and angles over all scenes
/// (per topology; for the trees learned from all sets, the measure, and for held-out
/// sets). Targets whose rows were not measured are left out.
std::vector<PredictionTarget> checkPredictionTargets(const std::vector<RuntimeRow>& synthetic,
                                                     const std::vector<AccuracyRow>& combined);

/// "met"/"MISSED" per target and a count, as `asr bench recognition` prints them.
void printPredictionTargets(std::ostream& out, const std::vector<PredictionTarget>& targets);

nlohmann::ordered_json targetsToJson(const std::vector<PredictionTarget>& targets);

}  // namespace asr_pose_prediction::bench
