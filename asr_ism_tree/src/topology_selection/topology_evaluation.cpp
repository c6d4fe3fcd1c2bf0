#include "asr_ism_tree/topology_selection/topology_evaluation.hpp"

#include <chrono>

#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"

namespace asr_ism_tree {

TopologyMeasures evaluateTopology(const asr_ism::Demonstration& demonstration,
                                  const RelationTopology& topology, const TestConfigurations& tests,
                                  const asr_ism::IsmRecognitionParameters& parameters,
                                  double threshold, double max_mean_work) {
  const IsmTree tree = generateIsmTree(demonstration, topology, parameters);
  const TreeRecognizer recognizer(tree, selectionRecognitionParameters());
  TopologyMeasures measures;
  measures.relations = topology.relationCount();
  measures.isms = tree.isms.size();
  measures.height = tree.height();

  std::size_t work = 0;
  double total_ms = 0.0;
  const double max_work = max_mean_work > 0.0 ? max_mean_work * tests.size() : 0.0;
  // Recognises one configuration; true if it is accepted.
  auto accepted = [&](const asr_common::Configuration& configuration) {
    TreeRecognitionStats stats;
    const auto start = std::chrono::steady_clock::now();
    const auto instances = recognizer.recognize(configuration, &stats);
    total_ms +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    work += stats.isms.neighbourhood_votes;
    return !instances.empty() && instances.front().confidence >= threshold;
  };
  auto overBudget = [&] { return max_work > 0.0 && static_cast<double>(work) > max_work; };
  std::size_t true_positives = 0, valid_seen = 0, invalid_seen = 0;
  for (const auto& configuration : tests.valid) {
    if (overBudget())
      break;
    true_positives += accepted(configuration);
    ++valid_seen;
  }
  for (const auto& configuration : tests.invalid) {
    if (overBudget())
      break;
    measures.false_positives += accepted(configuration);
    ++invalid_seen;
  }
  measures.over_budget = overBudget();

  const double count = static_cast<double>(valid_seen + invalid_seen);
  measures.false_positive_rate =
      invalid_seen == 0 ? 0.0 : static_cast<double>(measures.false_positives) / invalid_seen;
  measures.true_positive_rate =
      valid_seen == 0 ? 1.0 : static_cast<double>(true_positives) / valid_seen;
  measures.mean_ms = count > 0 ? total_ms / count : 0.0;
  measures.mean_work = count > 0 ? static_cast<double>(work) / count : 0.0;
  return measures;
}

}  // namespace asr_ism_tree
