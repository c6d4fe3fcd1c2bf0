#include "recognition_benchmark.hpp"

#include <memory>
#include <ostream>

#include "asr_common/cli/recordings_folder.hpp"
#include "asr_common/cli/timing.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism/thread_pool.hpp"
#include "asr_ism_tree/star_center.hpp"
#include "tree_measurement.hpp"

namespace asr_ism_tree::bench {

using asr_common::cli::evenlySpaced;
using asr_common::cli::maximum;
using asr_common::cli::median;
namespace {

SceneRow measure(const asr_ism::Demonstration& demonstration, const std::string& topology_name,
                 const RelationTopology& topology, const BenchmarkSettings& settings,
                 asr_ism::ThreadPool* pool) {
  SceneRow row;
  row.scene = demonstration.scene();
  row.topology = topology_name;
  row.objects = demonstration.objectCount();
  row.sets = demonstration.stepCount();

  const LearnedTree learned = learnAndStore(demonstration, topology, settings);
  row.learn_ms = learned.learn_ms;
  row.isms = learned.tree.isms.size();
  row.height = learned.tree.height();
  row.votes = learned.tree.relativePoseCount();

  std::vector<asr_common::Configuration> sets;
  for (std::size_t step = 0; step < demonstration.stepCount(); ++step)
    sets.push_back(demonstration.configuration(step));
  const TreeRecognizer recognizer(learned.tree, TreeRecognitionParameters{}, pool);
  const RecognitionTiming timing = timeRecognition(recognizer, sets, settings);
  row.recog_median_ms = median(timing.milliseconds);
  row.recog_max_ms = maximum(timing.milliseconds);
  row.passes = timing.passes;
  row.recognised_fraction = recognisedFraction(timing.best_confidence);

  std::vector<asr_common::Configuration> sampled;
  const std::size_t sample_size =
      settings.missing_one_sets == 0 ? sets.size() : settings.missing_one_sets;
  for (std::size_t step : evenlySpaced(sets.size(), sample_size))
    sampled.push_back(sets[step]);
  row.missing_one_sets = sampled.size();
  row.missing_one_confidence = meanConfidenceWithOneLeftOut(recognizer, sampled);
  return row;
}

}  // namespace

std::vector<SceneRow> benchmarkKitchenScenes(const std::string& recordings,
                                             const BenchmarkSettings& settings,
                                             std::ostream& progress) {
  std::unique_ptr<asr_ism::ThreadPool> pool;
  if (settings.threads > 1)
    pool = std::make_unique<asr_ism::ThreadPool>(settings.threads);
  std::vector<SceneRow> rows;
  for (const asr_common::cli::KitchenScene& kitchen_scene : asr_common::cli::kitchenScenes()) {
    const asr_ism::Demonstration demonstration = asr_ism::sqlite::readDemonstration(
        recordings + "/" + kitchen_scene.file, kitchen_scene.scene);
    const std::size_t center = chooseStarCenter(demonstration);
    progress << "  " << kitchen_scene.scene << ": star ..." << std::flush;
    rows.push_back(measure(demonstration, "star",
                           RelationTopology::star(demonstration.objects(), center), settings,
                           pool.get()));
    rows.back().star_center = demonstration.objects()[center].toString();
    progress << " complete ..." << std::flush;
    rows.push_back(measure(demonstration, "complete",
                           RelationTopology::complete(demonstration.objects()), settings,
                           pool.get()));
    progress << " done\n";
  }
  return rows;
}

}  // namespace asr_ism_tree::bench
