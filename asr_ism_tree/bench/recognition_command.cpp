#include "recognition_command.hpp"

#include <iostream>

#include "asr_common/atomic_file.hpp"
#include "asr_common/cli/command_line.hpp"
#include "asr_common/cli/recordings_folder.hpp"
#include "asr_common/input_error.hpp"
#include "asr_ism_tree/topology_selection/topology_selection.hpp"
#include "clutter_benchmark.hpp"
#include "recognition_benchmark.hpp"
#include "report.hpp"
#include "synthetic_benchmark.hpp"
#include "targets.hpp"

namespace asr_ism_tree::bench {
namespace {

using asr_common::cli::CommandLine;
using asr_common::cli::UsageError;

}  // namespace

int runRecognitionCommand(const std::vector<std::string>& arguments) {
  const CommandLine options(arguments, {"recordings", "threads", "synthetic-json", "max-votes"},
                            {"json", "no-synthetic", "no-clutter", "clutter-only"});
  BenchmarkSettings settings;
  settings.threads = static_cast<unsigned>(options.integer("threads", 1, 1, kMaxThreads));
  settings.exact_search_max_votes =
      static_cast<std::size_t>(options.integer("max-votes", 0, 0, 1LL << 40));
  const bool json = options.flag("json");
  const std::string synthetic_json = options.optional("synthetic-json", "");
  // In JSON mode stdout carries only the scene array, so the synthetic rows need a file.
  const bool run_synthetic = !options.flag("no-synthetic") && !options.flag("clutter-only") &&
                             (!json || !synthetic_json.empty());
  std::ostream& progress = std::cerr;

  const bool clutter_only = options.flag("clutter-only");
  std::vector<SceneRow> scene_rows;
  std::vector<ClutterRow> clutter_rows, jittered_clutter_rows;
  const auto recordings =
      asr_common::cli::benchmarkRecordings(options, ASR_RECORDINGS_DIR, "asr_bench", progress);
  if (recordings) {
    progress << "kitchen scenes from " << *recordings << "\n";
    if (!clutter_only)
      scene_rows = benchmarkKitchenScenes(*recordings, settings, progress);
    if (!options.flag("no-clutter")) {
      clutter_rows = benchmarkClutter(*recordings, settings, progress);
      jittered_clutter_rows = benchmarkJitteredClutter(*recordings, settings, progress);
    }
  }

  std::vector<SyntheticRow> synthetic_rows;
  if (run_synthetic) {
    progress << "synthetic scaling (objects per step count)\n";
    synthetic_rows = benchmarkSyntheticScaling(settings, progress);
    if (!synthetic_json.empty()) {
      asr_common::writeFileAtomically(synthetic_json,
                                      syntheticRowsToJson(synthetic_rows).dump(2) + "\n");
      progress << "synthetic rows written to " << synthetic_json << "\n";
    }
  } else if (json && !options.flag("no-synthetic")) {
    progress << "asr_bench: synthetic scaling skipped (with --json, give --synthetic-json FILE "
                "to run it)\n";
  }

  const std::vector<asr_common::cli::Target> checks =
      checkTargets(scene_rows, synthetic_rows, clutter_rows, jittered_clutter_rows);
  if (json) {
    std::cout << sceneRowsToJson(scene_rows).dump(2) << "\n";
    asr_common::cli::printTargets(progress, checks);
    return 0;
  }
  std::cout << "\n";
  if (!scene_rows.empty()) {
    printSceneTable(std::cout, scene_rows, settings);
    std::cout << "\n";
  } else if (!recordings) {
    std::cout << "Kitchen scenes: skipped, recordings folder not found\n\n";
  }
  if (!clutter_rows.empty()) {
    printClutterTable(std::cout, clutter_rows);
    std::cout << "\n";
    printJitteredClutterTable(std::cout, jittered_clutter_rows);
    std::cout << "\n";
  }
  if (!synthetic_rows.empty()) {
    printSyntheticTable(std::cout, synthetic_rows, settings);
    std::cout << "\n";
  }
  asr_common::cli::printTargets(std::cout, checks);
  return 0;
}

}  // namespace asr_ism_tree::bench
