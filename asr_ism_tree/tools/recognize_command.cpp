#include <chrono>
#include <iostream>

#include "asr_common/cli/command_line.hpp"
#include "asr_common/input_error.hpp"
#include "asr_ism_tree/cli/configuration_source.hpp"
#include "asr_ism_tree/cli/scene_instance_output.hpp"
#include "asr_ism_tree/sqlite/model_store.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"
#include "commands.hpp"

namespace asr_ism_tree::tools {

using asr_common::cli::CommandLine;
using asr_common::cli::UsageError;

int runRecognize(const std::vector<std::string>& arguments) {
  const CommandLine options(
      arguments, {"model", "scene", "objects", "demo", "set", "max-estimates"}, {"json"});
  const std::string model_path = options.required("model");
  const std::string scene = options.required("scene");
  TreeRecognitionParameters parameters;
  // Larger configurations are refused before any work, with the count and the limit.
  parameters.max_estimates = static_cast<std::size_t>(options.integer(
      "max-estimates", static_cast<long long>(parameters.max_estimates), 1, 1000000));
  const asr_common::Configuration configuration = cli::loadConfiguration(options, scene);
  const IsmTree tree = sqlite::loadIsmTree(model_path, scene);
  const TreeRecognizer recognizer(tree, parameters);

  const auto start = std::chrono::steady_clock::now();
  const std::vector<SceneInstance> instances = recognizer.recognize(configuration);
  const double runtime_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  if (options.flag("json")) {
    nlohmann::ordered_json json;
    json["scene"] = scene;
    json["runtime_ms"] = runtime_ms;
    json["instances"] = nlohmann::ordered_json::array();
    for (const SceneInstance& instance : instances) {
      json["instances"].push_back(cli::instanceToJson(instance));
    }
    std::cout << json.dump(2) << "\n";
    return 0;
  }
  std::cout << "scene '" << scene << "': " << instances.size()
            << (instances.size() == 1 ? " instance" : " instances") << " in "
            << configuration.size() << " objects (" << runtime_ms << " ms)\n";
  cli::printInstances(std::cout, instances);
  return 0;
}

}  // namespace asr_ism_tree::tools
