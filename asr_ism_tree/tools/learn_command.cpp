#include <chrono>
#include <cmath>
#include <iostream>

#include "asr_common/cli/command_line.hpp"
#include "asr_common/object_name.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism_tree/cli/recognition_options.hpp"
#include "asr_ism_tree/sqlite/model_store.hpp"
#include "asr_ism_tree/star_center.hpp"
#include "asr_ism_tree/topology_file.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "commands.hpp"

namespace asr_ism_tree::tools {

using asr_common::cli::CommandLine;
using asr_common::cli::UsageError;

int runLearn(const std::vector<std::string>& arguments) {
  const CommandLine options(
      arguments, {"demo", "scene", "topology", "star-center", "model", "bin-size", "max-angle-deg"},
      {});
  const std::string demo_path = options.required("demo");
  const std::string scene = options.required("scene");
  const std::string topology_spec = options.required("topology");
  const std::string model_path = options.required("model");
  const asr_ism::IsmRecognitionParameters parameters = cli::recognitionParametersFrom(options);
  if (options.has("star-center") && topology_spec != "star") {
    throw UsageError{"--star-center only applies to --topology star"};
  }

  const auto start = std::chrono::steady_clock::now();
  const asr_ism::Demonstration demonstration = asr_ism::sqlite::readDemonstration(demo_path, scene);
  RelationTopology topology;
  std::string topology_description;
  if (topology_spec == "star") {
    const std::size_t center =
        options.has("star-center")
            ? asr_common::resolveObjectName(options.required("star-center"),
                                            demonstration.objects(), "--star-center")
            : chooseStarCenter(demonstration);
    topology = RelationTopology::star(demonstration.objects(), center);
    topology_description = "star centred on " + demonstration.objects()[center].toString();
  } else if (topology_spec == "complete") {
    topology = RelationTopology::complete(demonstration.objects());
    topology_description = "complete";
  } else {
    topology = readTopologyFile(topology_spec, demonstration.objects());
    topology_description = "from " + topology_spec;
  }
  const IsmTree tree = generateIsmTree(demonstration, topology, parameters);
  sqlite::saveIsmTree(model_path, tree,
                      "demonstration " + demo_path + ", topology " + topology_description);
  const double elapsed_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  std::cout << "learned scene '" << scene << "' from " << demo_path << " ("
            << demonstration.stepCount() << " time steps, " << demonstration.objectCount()
            << " objects)\n"
            << "  topology: " << topology_description << ", " << topology.relationCount()
            << " relations\n"
            << "  tree: " << tree.isms.size() << " ISMs in " << tree.height() << " levels, "
            << tree.leafCount() << " leaves, " << tree.relativePoseCount() << " relative poses\n"
            << "  stored in " << model_path << " (" << elapsed_ms << " ms)\n";
  return 0;
}

}  // namespace asr_ism_tree::tools
