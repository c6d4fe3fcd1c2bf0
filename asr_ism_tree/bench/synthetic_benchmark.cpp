#include "synthetic_benchmark.hpp"

#include <memory>
#include <ostream>

#include "asr_common/cli/timing.hpp"
#include "asr_ism/synthetic_demonstration.hpp"
#include "asr_ism/thread_pool.hpp"
#include "tree_measurement.hpp"

namespace asr_ism_tree::bench {

using asr_common::cli::evenlySpaced;
using asr_common::cli::maximum;
using asr_common::cli::median;

std::vector<std::size_t> syntheticObjectCounts() {
  return {2, 3, 4, 5, 6, 7, 8, 9, 10};
}

std::vector<std::size_t> syntheticStepCounts() {
  return {100, 200, 400, 1000};
}

std::vector<SyntheticRow> benchmarkSyntheticScaling(const BenchmarkSettings& settings,
                                                    std::ostream& progress) {
  std::unique_ptr<asr_ism::ThreadPool> pool;
  if (settings.threads > 1)
    pool = std::make_unique<asr_ism::ThreadPool>(settings.threads);
  std::vector<SyntheticRow> rows;
  for (std::size_t steps : syntheticStepCounts()) {
    progress << "  " << steps << " steps:" << std::flush;
    for (std::size_t objects : syntheticObjectCounts()) {
      progress << " " << objects << std::flush;
      const asr_ism::Demonstration demonstration =
          asr_ism::makeSyntheticDemonstration(objects, steps, settings.synthetic_seed);
      SyntheticRow row;
      row.objects = objects;
      row.steps = steps;
      const LearnedTree learned = learnAndStore(
          demonstration, RelationTopology::complete(demonstration.objects()), settings);
      row.learn_ms = learned.learn_ms;
      row.isms = learned.tree.isms.size();
      row.height = learned.tree.height();
      row.votes = learned.tree.relativePoseCount();

      std::vector<asr_common::Configuration> sampled;
      for (std::size_t step : evenlySpaced(steps, settings.synthetic_configurations))
        sampled.push_back(demonstration.configuration(step));
      const TreeRecognizer recognizer(learned.tree, TreeRecognitionParameters{}, pool.get());
      const RecognitionTiming timing = timeRecognition(recognizer, sampled, settings);
      row.configurations = sampled.size();
      row.recog_median_ms = median(timing.milliseconds);
      row.recog_max_ms = maximum(timing.milliseconds);
      row.passes = timing.passes;
      row.recognised_fraction = recognisedFraction(timing.best_confidence);
      rows.push_back(row);
    }
    progress << "\n";
  }
  return rows;
}

}  // namespace asr_ism_tree::bench
