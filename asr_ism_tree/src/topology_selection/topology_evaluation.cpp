#include "asr_ism_tree/topology_selection/topology_evaluation.hpp"

#include <chrono>

#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"

namespace asr_ism_tree {

TopologyMeasures evaluateTopology(const asr_ism::Demonstration& demonstration,
                                  const RelationTopology& topology, const TestConfigurations& tests,
                                  const asr_ism::IsmRecognitionParameters& parameters,
                                  double threshold) {
  const IsmTree tree = generateIsmTree(demonstration, topology, parameters);
  const TreeRecognizer recognizer(tree);
  TopologyMeasures measures;
  measures.relations = topology.relationCount();
  measures.isms = tree.isms.size();
  measures.height = tree.height();

  std::size_t work = 0;
  double total_ms = 0.0;
  // Recognises one configuration; true if it is accepted.
  auto accepted = [&](const asr_ism::Configuration& configuration) {
    TreeRecognitionStats stats;
    const auto start = std::chrono::steady_clock::now();
    const auto instances = recognizer.recognize(configuration, &stats);
    total_ms +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    work += stats.isms.comparisons;
    return !instances.empty() && instances.front().confidence >= threshold;
  };
  std::size_t true_positives = 0;
  for (const auto& configuration : tests.valid)
    true_positives += accepted(configuration);
  for (const auto& configuration : tests.invalid)
    measures.false_positives += accepted(configuration);

  const double count = static_cast<double>(tests.size());
  measures.false_positive_rate =
      tests.invalid.empty() ? 0.0
                            : static_cast<double>(measures.false_positives) / tests.invalid.size();
  measures.true_positive_rate =
      tests.valid.empty() ? 1.0 : static_cast<double>(true_positives) / tests.valid.size();
  measures.mean_ms = count > 0 ? total_ms / count : 0.0;
  measures.mean_work = count > 0 ? static_cast<double>(work) / count : 0.0;
  return measures;
}

}  // namespace asr_ism_tree
