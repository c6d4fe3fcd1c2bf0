#include "predict_command.hpp"

#include <iostream>
#include <limits>

#include "asr_common/cli/command_line.hpp"
#include "asr_common/cli/timing.hpp"
#include "asr_common/input_error.hpp"
#include "asr_common/object_name.hpp"
#include "asr_ism_tree/cli/configuration_source.hpp"
#include "asr_ism_tree/sqlite/model_store.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"
#include "prediction_output.hpp"

namespace asr_pose_prediction::tools {

using asr_common::cli::CommandLine;
using asr_common::cli::UsageError;

namespace {

// Where the objects came from, to name it when no instance is found.
std::string sourceOf(const CommandLine& options) {
  return options.has("objects") ? options.required("objects")
                                : options.required("demo") + " set " + options.required("set");
}

}  // namespace

int runPredict(const std::vector<std::string>& arguments) {
  const CommandLine options(
      arguments,
      {"model", "scene", "objects", "demo", "set", "samples", "seed", "instances", "object"},
      {"json", "summary"});
  const std::string model_path = options.required("model");
  const std::string scene = options.required("scene");
  PredictionOptions prediction_options;
  prediction_options.samples =
      static_cast<std::size_t>(options.integer("samples", 100, 1, kMaxSamples));
  prediction_options.seed = static_cast<std::uint32_t>(
      options.integer("seed", 0, 0, std::numeric_limits<std::uint32_t>::max()));
  prediction_options.instances =
      static_cast<std::size_t>(options.integer("instances", 1, 1, kMaxInstances));

  const asr_ism_tree::IsmTree tree = asr_ism_tree::sqlite::loadIsmTree(model_path, scene);
  const PosePredictor predictor(tree);
  if (options.has("object")) {
    prediction_options.object = tree.objects()[asr_common::resolveObjectName(
        options.required("object"), tree.objects(), "--object")];
  }
  const asr_common::Configuration configuration =
      asr_ism_tree::cli::loadConfiguration(options, scene);

  const asr_ism_tree::TreeRecognizer recognizer(tree);
  std::vector<SceneInstance> instances = recognizer.recognize(configuration);
  if (instances.empty()) {
    throw asr_common::InputError("no instance of scene '" + scene + "' found in " +
                                 sourceOf(options) + ", so there is nothing to predict from");
  }
  PredictionReport report;
  report.scene = scene;
  report.samples = prediction_options.samples;
  report.several_instances = prediction_options.instances > 1;
  report.summary = options.flag("summary");
  report.runtime_ms = asr_common::cli::millisecondsOf(
      [&] { report.predictions = predictor.predict(instances, prediction_options); });
  instances.resize(std::min(instances.size(), prediction_options.instances));
  report.instances = instances;

  if (options.flag("json"))
    std::cout << predictionReportToJson(report).dump(2) << "\n";
  else
    printPredictionReport(std::cout, report);
  return 0;
}

}  // namespace asr_pose_prediction::tools
