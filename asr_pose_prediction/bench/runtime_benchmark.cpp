#include "runtime_benchmark.hpp"

#include <algorithm>
#include <limits>
#include <ostream>

#include "asr_common/cli/recordings_folder.hpp"
#include "asr_common/cli/timing.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism/synthetic_demonstration.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"
#include "asr_pose_prediction/pose_predictor.hpp"

namespace asr_pose_prediction::bench {
namespace {

using asr_common::cli::evenlySpaced;

RuntimeRow measure(const asr_ism::Demonstration& demonstration, const BenchmarkTree& learned,
                   std::size_t configurations, const PredictionBenchmarkSettings& settings) {
  const asr_ism_tree::IsmTree& tree = learned.tree;
  RuntimeRow row;
  row.scene = demonstration.scene();
  row.topology = learned.topology;
  row.objects = demonstration.objectCount();
  row.steps = demonstration.stepCount();
  row.isms = tree.isms.size();
  row.height = tree.height();
  row.votes = tree.relativePoseCount();
  row.samples = settings.samples;

  const PosePredictor predictor(tree);
  for (std::size_t object = 0; object < predictor.objects().size(); ++object)
    row.longest_path = std::max(row.longest_path, predictor.path(object).steps.size());
  const asr_ism_tree::TreeRecognizer recognizer(tree);
  PredictionOptions options;
  options.samples = settings.samples;
  options.seed = settings.seed;

  std::vector<double> fastest;
  for (std::size_t step : evenlySpaced(demonstration.stepCount(), configurations)) {
    const std::vector<SceneInstance> instances =
        recognizer.recognize(demonstration.configuration(step));
    if (instances.empty())
      continue;
    // Without its objects the instance contains none of them, so all are predicted.
    std::vector<SceneInstance> bare = {instances.front()};
    bare.front().objects.clear();
    double best = std::numeric_limits<double>::infinity();
    for (int repetition = 0; repetition < std::max(1, settings.repetitions); ++repetition) {
      std::vector<ObjectPrediction> predictions;
      best = std::min(best, asr_common::cli::millisecondsOf(
                                [&] { predictions = predictor.predict(bare, options); }));
      if (predictions.size() != row.objects)
        throw std::logic_error("benchmark: not every object of the scene was predicted");
    }
    fastest.push_back(best);
  }
  row.instances = fastest.size();
  row.median_ms = asr_common::cli::median(fastest);
  row.max_ms = asr_common::cli::maximum(fastest);
  return row;
}

}  // namespace

std::vector<std::size_t> syntheticObjectCounts() {
  return {2, 3, 4, 5, 6, 7, 8, 9, 10};
}

std::vector<std::size_t> syntheticStepCounts() {
  return {100, 200, 400, 1000};
}

std::vector<RuntimeRow> benchmarkKitchenRuntime(const std::string& recordings,
                                                const PredictionBenchmarkSettings& settings,
                                                std::ostream& progress) {
  std::vector<RuntimeRow> rows;
  for (const asr_common::cli::KitchenScene& kitchen_scene : asr_common::cli::kitchenScenes()) {
    progress << "  " << kitchen_scene.scene << std::flush;
    const asr_ism::Demonstration demonstration = asr_ism::sqlite::readDemonstration(
        recordings + "/" + kitchen_scene.file, kitchen_scene.scene);
    for (const BenchmarkTree& learned : learnStarAndComplete(demonstration))
      rows.push_back(measure(demonstration, learned, settings.timing_sets, settings));
    progress << "\n";
  }
  return rows;
}

std::vector<RuntimeRow> benchmarkSyntheticRuntime(const PredictionBenchmarkSettings& settings,
                                                  std::ostream& progress) {
  std::vector<RuntimeRow> rows;
  for (std::size_t steps : syntheticStepCounts()) {
    progress << "  " << steps << " steps:" << std::flush;
    for (std::size_t objects : syntheticObjectCounts()) {
      progress << " " << objects << std::flush;
      const asr_ism::Demonstration demonstration =
          asr_ism::makeSyntheticDemonstration(objects, steps, settings.synthetic_seed);
      for (const BenchmarkTree& learned : learnStarAndComplete(demonstration))
        rows.push_back(
            measure(demonstration, learned, settings.synthetic_configurations, settings));
    }
    progress << "\n";
  }
  return rows;
}

}  // namespace asr_pose_prediction::bench
