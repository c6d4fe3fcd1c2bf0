#pragma once

#include <iosfwd>
#include <vector>

#include "benchmark_settings.hpp"

namespace asr_ism_tree::bench {

/// One synthetic demonstration (complete topology) of a given size.
struct SyntheticRow {
  std::size_t objects = 0;
  std::size_t steps = 0;
  std::size_t isms = 0;
  int height = 0;
  std::size_t votes = 0;
  double learn_ms = 0.0;
  std::size_t configurations = 0;  // own steps recognised
  double recog_median_ms = 0.0;
  double recog_max_ms = 0.0;
  int passes = 0;
  double recognised_fraction = 0.0;
};

/// Object counts and step counts of the scaling run.
std::vector<std::size_t> syntheticObjectCounts();
std::vector<std::size_t> syntheticStepCounts();

/// Learns complete-topology trees of makeSyntheticDemonstration for every size and times the
/// recognition of evenly spaced steps of each demonstration. Progress goes to `progress`.
std::vector<SyntheticRow> benchmarkSyntheticScaling(const BenchmarkSettings& settings,
                                                    std::ostream& progress);

}  // namespace asr_ism_tree::bench
