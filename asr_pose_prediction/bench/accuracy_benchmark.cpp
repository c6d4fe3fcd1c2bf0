#include "accuracy_benchmark.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <utility>

#include "asr_common/cli/recordings_folder.hpp"
#include "asr_common/cli/timing.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"
#include "asr_pose_prediction/prediction_accuracy.hpp"

namespace asr_pose_prediction::bench {
namespace {

constexpr double kDegreesPerRadian = 180.0 / M_PI;

// The demonstration without recorded set `left_out`.
asr_ism::Demonstration withoutStep(const asr_ism::Demonstration& demonstration,
                                   std::size_t left_out) {
  asr_ism::Demonstration rest(demonstration.scene(), demonstration.objects());
  for (std::size_t step = 0; step < demonstration.stepCount(); ++step) {
    if (step == left_out)
      continue;
    const std::size_t added = rest.addStep();
    for (std::size_t object = 0; object < demonstration.objectCount(); ++object) {
      if (const auto& pose = demonstration.pose(step, object))
        rest.setPose(added, object, *pose);
    }
  }
  return rest;
}

// Every object of recorded set `step` left out in turn and predicted with `tree`.
void measureSet(const asr_ism::Demonstration& demonstration, std::size_t step,
                const asr_ism_tree::IsmTree& tree, const PredictionBenchmarkSettings& settings,
                AccuracyRow& row) {
  const PosePredictor predictor(tree);
  const asr_ism_tree::TreeRecognizer recognizer(tree);
  const asr_common::Configuration configuration = demonstration.configuration(step);
  ++row.sets;
  for (std::size_t left_out = 0; left_out < configuration.size(); ++left_out) {
    const LeftOutPrediction outcome = predictLeftOutObject(
        recognizer, predictor, configuration, left_out, settings.accuracy_samples,
        settings.seed + static_cast<std::uint32_t>(step));
    ++row.cases;
    if (!outcome.instance_found) {
      ++row.no_instance;
      const double never = std::numeric_limits<double>::infinity();
      row.distances_m.push_back(never);
      row.angles_at_nearest_deg.push_back(never);
      row.smallest_angles_deg.push_back(never);
      continue;
    }
    row.distances_m.push_back(outcome.error.distance);
    row.angles_at_nearest_deg.push_back(outcome.error.angle_at_nearest * kDegreesPerRadian);
    row.smallest_angles_deg.push_back(outcome.error.smallest_angle * kDegreesPerRadian);
  }
}

// The in-sample and the held-out row of one scene and tree.
std::vector<AccuracyRow> measure(const asr_ism::Demonstration& demonstration,
                                 const BenchmarkTree& learned,
                                 const PredictionBenchmarkSettings& settings) {
  std::vector<AccuracyRow> rows(2);
  for (AccuracyRow& row : rows) {
    row.scene = demonstration.scene();
    row.topology = learned.topology;
  }
  rows[1].held_out = true;
  const std::size_t sets =
      settings.accuracy_sets == 0 ? demonstration.stepCount() : settings.accuracy_sets;
  for (std::size_t step : asr_common::cli::evenlySpaced(demonstration.stepCount(), sets)) {
    measureSet(demonstration, step, learned.tree, settings, rows[0]);
    const asr_ism_tree::IsmTree without_set = asr_ism_tree::generateIsmTree(
        withoutStep(demonstration, step), learned.tree.topology, learned.tree.parameters);
    measureSet(demonstration, step, without_set, settings, rows[1]);
  }
  return rows;
}

void append(std::vector<double>& to, const std::vector<double>& values) {
  to.insert(to.end(), values.begin(), values.end());
}

}  // namespace

Distribution distributionOf(std::vector<double> values) {
  Distribution distribution;
  if (values.empty())
    return distribution;
  std::sort(values.begin(), values.end());
  distribution.median = asr_common::cli::median(values);
  const auto rank = static_cast<std::size_t>(std::ceil(0.9 * static_cast<double>(values.size())));
  distribution.p90 = values[std::max<std::size_t>(rank, 1) - 1];
  distribution.max = values.back();
  return distribution;
}

std::vector<AccuracyRow> benchmarkKitchenAccuracy(const std::string& recordings,
                                                  const PredictionBenchmarkSettings& settings,
                                                  std::ostream& progress) {
  std::vector<AccuracyRow> rows;
  for (const asr_common::cli::KitchenScene& kitchen_scene : asr_common::cli::kitchenScenes()) {
    progress << "  " << kitchen_scene.scene << std::flush;
    const asr_ism::Demonstration demonstration = asr_ism::sqlite::readDemonstration(
        recordings + "/" + kitchen_scene.file, kitchen_scene.scene);
    for (const BenchmarkTree& learned : learnStarAndComplete(demonstration)) {
      progress << " " << learned.topology << std::flush;
      for (AccuracyRow& row : measure(demonstration, learned, settings))
        rows.push_back(std::move(row));
    }
    progress << "\n";
  }
  return rows;
}

AccuracyRow combinedAccuracy(const std::vector<AccuracyRow>& rows, const std::string& topology,
                             bool held_out) {
  AccuracyRow combined;
  combined.scene = "all";
  combined.topology = topology;
  combined.held_out = held_out;
  for (const AccuracyRow& row : rows) {
    if (row.topology != topology || row.held_out != held_out)
      continue;
    combined.sets += row.sets;
    combined.cases += row.cases;
    combined.no_instance += row.no_instance;
    append(combined.distances_m, row.distances_m);
    append(combined.angles_at_nearest_deg, row.angles_at_nearest_deg);
    append(combined.smallest_angles_deg, row.smallest_angles_deg);
  }
  return combined;
}

}  // namespace asr_pose_prediction::bench
