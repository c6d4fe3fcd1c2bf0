#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "benchmark_settings.hpp"

namespace asr_ism_tree::bench {

/// One kitchen scene learned with one topology.
struct SceneRow {
  std::string scene;
  std::string topology;     // "star" or "complete"
  std::string star_center;  // the star's centre object, empty for complete
  std::size_t objects = 0;
  std::size_t sets = 0;
  std::size_t isms = 0;
  int height = 0;
  std::size_t votes = 0;  // relative poses over the tree
  double learn_ms = 0.0;
  double recog_median_ms = 0.0;
  double recog_max_ms = 0.0;
  int passes = 0;
  double recognised_fraction = 0.0;
  double missing_one_confidence = 0.0;
  std::size_t missing_one_sets = 0;  // sets the left-out measure used
};

/// Learns every kitchen scene from `recordings` with a star (centre by chooseStarCenter) and a
/// complete topology and measures learning and recognition of its own recorded sets. Progress
/// goes to `progress`.
std::vector<SceneRow> benchmarkKitchenScenes(const std::string& recordings,
                                             const BenchmarkSettings& settings,
                                             std::ostream& progress);

}  // namespace asr_ism_tree::bench
