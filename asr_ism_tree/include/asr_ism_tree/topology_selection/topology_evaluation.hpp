#pragma once

#include <cstddef>

#include "asr_ism/demonstration.hpp"
#include "asr_ism/ism_recognizer.hpp"
#include "asr_ism_tree/relation_topology.hpp"
#include "asr_ism_tree/topology_selection/test_configurations.hpp"

namespace asr_ism_tree {

/// How a relation topology's tree does on the test configurations.
struct TopologyMeasures {
  std::size_t relations = 0;
  std::size_t isms = 0;
  int height = 0;
  /// numFPs: share of the invalid configurations recognised with confidence >= the threshold.
  double false_positive_rate = 0.0;
  std::size_t false_positives = 0;
  /// Share of the valid configurations recognised with confidence >= the threshold.
  double true_positive_rate = 0.0;
  /// avgDur: mean wall-clock recognition time per configuration (machine dependent).
  double mean_ms = 0.0;
  /// Mean vote-to-hypothesis comparisons per configuration: the machine-independent cost.
  double mean_work = 0.0;
  /// The evaluation stopped early because the work exceeded `max_mean_work`: the rates and means
  /// cover only the configurations recognised before that, and the topology is over budget.
  bool over_budget = false;
};

/// Learns the tree of `topology` and recognises every test configuration with it (on the
/// calling thread). Stops early, marking the result over budget, once the work exceeds
/// `max_mean_work` per configuration on average over all of them (no limit if <= 0): a search
/// need not finish measuring a topology it cannot use. Throws InputError for a disconnected
/// topology.
TopologyMeasures evaluateTopology(const asr_ism::Demonstration& demonstration,
                                  const RelationTopology& topology, const TestConfigurations& tests,
                                  const asr_ism::IsmRecognitionParameters& parameters,
                                  double threshold, double max_mean_work = 0.0);

}  // namespace asr_ism_tree
