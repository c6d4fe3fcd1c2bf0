#include <chrono>
#include <iostream>

#include "asr_ism/configuration_file.hpp"
#include "asr_ism/input_error.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism_tree/sqlite/model_store.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"
#include "command_line.hpp"
#include "commands.hpp"
#include "scene_instance_output.hpp"

namespace asr_ism_tree::tools {
namespace {

asr_ism::Configuration loadConfiguration(const CommandLine& options, const std::string& scene) {
  if (options.has("objects") == options.has("demo")) {
    throw UsageError{"give either --objects FILE or --demo DB --set K"};
  }
  if (options.has("objects")) {
    if (options.has("set"))
      throw UsageError{"--set goes with --demo, not --objects"};
    return asr_ism::readConfigurationFile(options.required("objects"));
  }
  const std::string demo_path = options.required("demo");
  const long long set = options.integer("set", -1);
  if (set < 0)
    throw UsageError{"--demo needs --set K"};
  const asr_ism::Demonstration demonstration = asr_ism::sqlite::readDemonstration(demo_path, scene);
  if (static_cast<std::size_t>(set) >= demonstration.stepCount()) {
    throw asr_ism::InputError(demo_path + ": scene '" + scene + "' has " +
                              std::to_string(demonstration.stepCount()) + " recorded sets; set " +
                              std::to_string(set) + " does not exist (sets count from 0)");
  }
  return demonstration.configuration(static_cast<std::size_t>(set));
}

}  // namespace

int runRecognize(const std::vector<std::string>& arguments) {
  const CommandLine options(arguments, {"model", "scene", "objects", "demo", "set"}, {"json"});
  const std::string model_path = options.required("model");
  const std::string scene = options.required("scene");
  const asr_ism::Configuration configuration = loadConfiguration(options, scene);
  const IsmTree tree = sqlite::loadIsmTree(model_path, scene);
  const TreeRecognizer recognizer(tree);

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
      json["instances"].push_back(instanceToJson(instance));
    }
    std::cout << json.dump(2) << "\n";
    return 0;
  }
  std::cout << "scene '" << scene << "': " << instances.size()
            << (instances.size() == 1 ? " instance" : " instances") << " in "
            << configuration.size() << " objects (" << runtime_ms << " ms)\n";
  printInstances(std::cout, instances);
  return 0;
}

}  // namespace asr_ism_tree::tools
