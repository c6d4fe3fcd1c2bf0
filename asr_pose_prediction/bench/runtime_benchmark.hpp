#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "benchmark_trees.hpp"

namespace asr_pose_prediction::bench {

/// How long predicting every object of one scene takes with one tree.
struct RuntimeRow {
  std::string scene;     // a kitchen scene, or "synthetic"
  std::string topology;  // "star" or "complete"
  std::size_t objects = 0;
  std::size_t steps = 0;  // demonstrated time steps (recorded sets)
  std::size_t isms = 0;
  int height = 0;
  std::size_t longest_path = 0;  // ISMs on the longest prediction path
  std::size_t votes = 0;         // relative poses over the tree
  std::size_t instances = 0;     // instances the prediction was timed from
  std::size_t samples = 0;       // poses per object
  double median_ms = 0.0;
  double max_ms = 0.0;
};

/// Every kitchen scene in `recordings`, star and complete trees: for the instances recognised in
/// evenly spaced recorded sets, the time PosePredictor::predict takes for `samples` poses of
/// every object of the scene (the instance's matched objects are dropped from it, so that every
/// object is predicted).
std::vector<RuntimeRow> benchmarkKitchenRuntime(const std::string& recordings,
                                                const PredictionBenchmarkSettings& settings,
                                                std::ostream& progress);

/// The same for makeSyntheticDemonstration of 2-10 objects x 100, 200, 400, 1000 steps.
std::vector<RuntimeRow> benchmarkSyntheticRuntime(const PredictionBenchmarkSettings& settings,
                                                  std::ostream& progress);

std::vector<std::size_t> syntheticObjectCounts();
std::vector<std::size_t> syntheticStepCounts();

}  // namespace asr_pose_prediction::bench
