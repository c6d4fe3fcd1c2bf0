#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "benchmark_trees.hpp"

namespace asr_pose_prediction::bench {

/// Median (mean of the middle two for an even count), 90th percentile (nearest rank: the
/// ceil(0.9 n)-th smallest) and maximum of some values.
struct Distribution {
  double median = 0.0;
  double p90 = 0.0;
  double max = 0.0;
};
Distribution distributionOf(std::vector<double> values);

/// The leave-one-out accuracy of one scene with one tree (or of several, combined): one case per
/// recorded set and object left out of it.
struct AccuracyRow {
  std::string scene;  // "all" for the combination of every scene
  std::string topology;
  /// false: the tree learned from every recorded set (the measure: the set left out from
  /// is part of the demonstration); true: for each set a tree learned without it.
  bool held_out = false;
  std::size_t sets = 0;
  std::size_t cases = 0;
  /// Cases where the rest gave no instance; they count as infinitely far in the distributions.
  std::size_t no_instance = 0;
  /// Per case: distance to the nearest predicted position (m), the angle of that pose and the
  /// smallest angle of any predicted pose (degrees).
  std::vector<double> distances_m;
  std::vector<double> angles_at_nearest_deg;
  std::vector<double> smallest_angles_deg;
};

/// For every kitchen scene in `recordings` and its star and complete trees: every object of every
/// recorded set (or of settings.accuracy_sets evenly spaced ones) left out, the rest recognised,
/// settings.accuracy_samples poses of it predicted from the best instance (seed: settings.seed
/// plus the set's index), compared with its recorded pose. One row per scene and topology with
/// the tree learned from all sets, and one held-out row, where each set is recognised and
/// predicted with a tree of the same topology learned from all other sets.
std::vector<AccuracyRow> benchmarkKitchenAccuracy(const std::string& recordings,
                                                  const PredictionBenchmarkSettings& settings,
                                                  std::ostream& progress);

/// The rows of one topology, in-sample or held-out, combined into one row, scene "all".
AccuracyRow combinedAccuracy(const std::vector<AccuracyRow>& rows, const std::string& topology,
                             bool held_out);

}  // namespace asr_pose_prediction::bench
