#include "predict_command.hpp"

#include <algorithm>
#include <iostream>
#include <limits>
#include <set>
#include <sstream>

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

// The types of `--hide TYPE[,TYPE]`, each checked to be a type of the scene.
std::set<std::string> hiddenTypes(const CommandLine& options, const asr_ism_tree::IsmTree& tree) {
  std::set<std::string> hidden;
  std::stringstream list(options.optional("hide", ""));
  for (std::string type; std::getline(list, type, ',');) {
    const auto& objects = tree.objects();
    if (std::none_of(objects.begin(), objects.end(),
                     [&](const asr_common::ObjectKey& key) { return key.type == type; })) {
      throw asr_common::InputError("--hide: scene '" + tree.scene + "' has no object of type '" +
                                   type + "'");
    }
    hidden.insert(type);
  }
  if (options.has("hide") && hidden.empty())
    throw UsageError{"--hide needs TYPE[,TYPE]"};
  return hidden;
}

// The configuration without the estimates of hidden types: what a robot that has not seen them
// yet would have.
asr_common::Configuration withoutTypes(asr_common::Configuration configuration,
                                       const std::set<std::string>& hidden) {
  configuration.erase(std::remove_if(configuration.begin(), configuration.end(),
                                     [&](const asr_common::ObjectEstimate& estimate) {
                                       return hidden.count(estimate.key.type) > 0;
                                     }),
                      configuration.end());
  return configuration;
}

}  // namespace

int runPredict(const std::vector<std::string>& arguments) {
  const CommandLine options(arguments,
                            {"model", "scene", "objects", "demo", "set", "hide", "samples", "seed",
                             "instances", "object"},
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
  const asr_common::Configuration configuration = withoutTypes(
      asr_ism_tree::cli::loadConfiguration(options, scene), hiddenTypes(options, tree));

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
