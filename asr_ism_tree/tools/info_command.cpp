#include <cmath>
#include <iostream>

#include "asr_common/cli/command_line.hpp"
#include "asr_common/input_error.hpp"
#include "asr_ism_tree/sqlite/model_store.hpp"
#include "commands.hpp"

namespace asr_ism_tree::tools {

using asr_common::cli::CommandLine;
using asr_common::cli::UsageError;
namespace {

void printIsm(const IsmTree& tree, int ism, int depth) {
  const std::string indent(2 * depth + 2, ' ');
  const auto& model = tree.isms[ism];
  std::cout << indent << "ISM " << model.name << " (level " << tree.level[ism] << ", reference "
            << model.reference.toString() << ", " << model.relativePoseCount()
            << " relative poses)\n";
  for (const auto& member : model.members) {
    std::cout << indent << "  " << (member.isPlaceholder() ? "placeholder " : "object ")
              << member.object.toString() << ": " << member.relative_poses.size()
              << " relative poses\n";
  }
  for (const auto& member : model.members) {
    if (member.isPlaceholder())
      printIsm(tree, member.child_ism, depth + 1);
  }
}

void printTree(const IsmTree& tree) {
  std::cout << "scene '" << tree.scene << "': " << tree.objects().size() << " objects, "
            << tree.topology.relationCount() << " relations, " << tree.isms.size() << " ISMs in "
            << tree.height() << " levels, " << tree.leafCount() << " leaves, "
            << tree.relativePoseCount() << " relative poses (bin size " << tree.parameters.bin_size
            << " m, max angle deviation " << tree.parameters.max_angle_deviation * 180.0 / M_PI
            << " deg)\n";
  std::cout << "  relations:";
  for (const auto& [a, b] : tree.topology.relations()) {
    std::cout << " " << tree.objects()[a].toString() << "--" << tree.objects()[b].toString();
  }
  std::cout << "\n";
  printIsm(tree, 0, 0);
}

}  // namespace

int runInfo(const std::vector<std::string>& arguments) {
  const CommandLine options(arguments, {"model", "scene"}, {});
  const std::string model_path = options.required("model");
  if (options.has("scene")) {
    printTree(sqlite::loadIsmTree(model_path, options.required("scene")));
    return 0;
  }
  const std::vector<std::string> scenes = sqlite::listModelScenes(model_path);
  if (scenes.empty()) {
    throw asr_common::InputError(model_path + ": contains no ISM tree model");
  }
  // Every scene is described; one that cannot be used is named with the reason, and the exit
  // code says that the file is not all usable.
  std::size_t invalid = 0;
  for (const std::string& scene : scenes) {
    try {
      printTree(sqlite::loadIsmTree(model_path, scene));
    } catch (const asr_ism::InputError& error) {
      ++invalid;
      std::cout << "scene '" << scene << "': INVALID model, recognisers refuse it: " << error.what()
                << "\n";
    }
  }
  if (invalid > 0) {
    throw asr_ism::InputError(model_path + ": " + std::to_string(invalid) + " of " +
                              std::to_string(scenes.size()) + " scene models are invalid");
  }
  return 0;
}

}  // namespace asr_ism_tree::tools
