#include <cstdio>
#include <iostream>

#include "asr_common/cli/command_line.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism_tree/cli/recognition_options.hpp"
#include "asr_ism_tree/cli/topology_selection_options.hpp"
#include "asr_ism_tree/sqlite/model_store.hpp"
#include "asr_ism_tree/topology_file.hpp"
#include "asr_ism_tree/topology_selection/topology_selection.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "commands.hpp"

namespace asr_ism_tree::tools {

using asr_common::cli::CommandLine;
using asr_common::cli::UsageError;

namespace {

void printMeasures(const char* name, const TopologyMeasures& measures) {
  std::printf(
      "  %-9s %3zu relations, %2zu ISMs, height %d: numFPs %6.2f %%, avgDur %7.3f ms, "
      "work %10.0f comparisons, valid recognised %6.2f %%\n",
      name, measures.relations, measures.isms, measures.height,
      100.0 * measures.false_positive_rate, measures.mean_ms, measures.mean_work,
      100.0 * measures.true_positive_rate);
}

// The search options of the command line: the shared ones, the tree height, the method and the
// recognition parameters.
TopologySelectionOptions selectionOptionsFrom(const CommandLine& options) {
  TopologySelectionOptions selection = cli::topologySelectionOptionsFrom(options, 0.0);
  selection.parameters = cli::recognitionParametersFrom(options);
  selection.max_tree_height =
      static_cast<int>(options.integer("max-height", 0, 0, kMaxTreeHeightOption));
  const std::string method = options.has("method") ? options.required("method") : "hill-climbing";
  if (method == "annealing")
    selection.method = TopologySearchMethod::kSimulatedAnnealing;
  else if (method != "hill-climbing")
    throw UsageError{"--method must be hill-climbing or annealing (got '" + method + "')"};
  if (options.has("tests-in") && options.has("tests-out"))
    throw UsageError{"--tests-in and --tests-out exclude each other"};
  return selection;
}

void printProgress(const TopologySelectionProgress& progress) {
  std::fprintf(stderr,
               "\rrelation topology selection: %zu/%zu topologies, cost %.4f, best %.4f, "
               "%.0f s, about %.0f s left   ",
               progress.evaluated, progress.max_evaluations, progress.current_cost,
               progress.best_cost, progress.seconds_elapsed, progress.seconds_left_estimate);
}

void printResult(const TopologySelectionResult& result, double max_duration_ms) {
  std::printf("  %zu test configurations: %zu valid, %zu invalid; %zu topologies evaluated\n",
              result.tests.size(), result.tests.valid.size(), result.tests.invalid.size(),
              result.evaluated);
  if (result.max_mean_work > 0)
    std::printf("  time budget %.3f ms per configuration = %.0f comparisons on this machine\n",
                max_duration_ms, result.max_mean_work);
  printMeasures("star", result.star_measures);
  printMeasures("optimised", result.measures);
  printMeasures("complete", result.complete_measures);
}

}  // namespace

int runSelectTopology(const std::vector<std::string>& arguments) {
  const CommandLine options(
      arguments,
      {"demo", "scene", "topology-out", "model", "tests", "seed", "alpha", "beta",
       "max-duration-ms", "max-height", "max-evaluations", "method", "start", "threads", "tests-in",
       "tests-out", "bin-size", "max-angle-deg"},
      {});
  const std::string demo_path = options.required("demo");
  const std::string scene = options.required("scene");
  const std::string topology_out = options.required("topology-out");
  const std::string model_path = options.required("model");
  TopologySelectionOptions selection = selectionOptionsFrom(options);

  const asr_ism::Demonstration demonstration = asr_ism::sqlite::readDemonstration(demo_path, scene);
  RelationTopology start;
  if (options.has("start")) {
    start = readTopologyFile(options.required("start"), demonstration.objects());
    selection.start = &start;
  }
  TestConfigurations stored_tests;
  if (options.has("tests-in"))
    stored_tests = readTestConfigurations(options.required("tests-in"), scene);
  const TopologySelectionResult result = selectTopology(
      demonstration, selection, printProgress, options.has("tests-in") ? &stored_tests : nullptr);
  std::fprintf(stderr, "\n");
  if (options.has("tests-out"))
    writeTestConfigurations(options.required("tests-out"), result.tests, demonstration.objects());

  // The model first, the topology file once the model is committed: a run that is killed or
  // fails in between leaves the previous topology file, never one whose model was not stored.
  const IsmTree tree = generateIsmTree(demonstration, result.topology, selection.parameters);
  sqlite::saveIsmTree(
      model_path, tree,
      "demonstration " + demo_path + ", topology selected by RTS (" + topology_out + ")");
  writeTopologyFile(topology_out, result.topology);

  std::printf("selected a relation topology for scene '%s' from %s\n", scene.c_str(),
              demo_path.c_str());
  printResult(result, selection.max_duration_ms);
  std::printf("  topology written to %s, tree (%zu ISMs) stored in %s\n", topology_out.c_str(),
              tree.isms.size(), model_path.c_str());
  return 0;
}

}  // namespace asr_ism_tree::tools
