#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "asr_ism/demonstration.hpp"
#include "asr_ism_tree/ism_tree.hpp"

namespace asr_pose_prediction::bench {

/// How the prediction benchmark measures; the defaults keep a full run within a few minutes.
struct PredictionBenchmarkSettings {
  /// Poses per object in the runtime measurement (the 100).
  std::size_t samples = 100;
  /// Poses of the left-out object in the accuracy measurement (the 200).
  std::size_t accuracy_samples = 200;
  /// Recorded sets (evenly spaced) whose instances the runtime is measured from.
  std::size_t timing_sets = 20;
  /// Recorded sets (evenly spaced) left out object by object; 0: every set.
  std::size_t accuracy_sets = 0;
  /// Evenly spaced steps of a synthetic demonstration whose instances are predicted from.
  std::size_t synthetic_configurations = 10;
  /// Each instance's prediction is timed this many times and the fastest time kept, which
  /// filters out interruptions by the system.
  int repetitions = 40;  // a prediction takes microseconds: the fastest of many is stable
  std::uint32_t seed = 1;
  std::uint32_t synthetic_seed = 1;
};

/// A tree the benchmark measures: the scene's demonstration learned with one topology.
struct BenchmarkTree {
  std::string topology;  // "star" or "complete"
  asr_ism_tree::IsmTree tree;
};

/// The demonstration learned with a star topology (centre by chooseStarCenter) and with a
/// complete one, default recognition parameters.
std::vector<BenchmarkTree> learnStarAndComplete(const asr_ism::Demonstration& demonstration);

}  // namespace asr_pose_prediction::bench
