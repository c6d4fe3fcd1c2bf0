#pragma once

#include <cstddef>
#include <cstdint>

namespace asr_ism_tree::bench {

/// How the benchmarks measure; the defaults keep a full run within a few minutes on two cores.
struct BenchmarkSettings {
  /// Threads of the pool the tree recognizer runs a level's ISMs on; 1: no pool.
  unsigned threads = 1;
  /// Recognition of the configurations is repeated up to this many passes and each
  /// configuration's fastest time is kept, which filters out interruptions by the system.
  int max_passes = 5;
  /// No further pass starts once one tree's passes have taken this long.
  double pass_budget_ms = 3000.0;
  /// Learning (incl. storage) is repeated this many times and the fastest time kept.
  int learn_repetitions = 3;
  /// Recorded sets (evenly spaced) used for the one-object-left-out confidence; 0: every set.
  std::size_t missing_one_sets = 0;
  /// Configurations (evenly spaced steps) recognised per synthetic demonstration.
  std::size_t synthetic_configurations = 20;
  std::uint32_t synthetic_seed = 1;
  /// The clutter series' TreeRecognitionParameters::exact_search_max_votes; 0: its default.
  std::size_t exact_search_max_votes = 0;
};

}  // namespace asr_ism_tree::bench
