#include "prediction_command.hpp"

#include <iostream>
#include <limits>
#include <optional>

#include "asr_common/cli/command_line.hpp"
#include "asr_common/cli/recordings_folder.hpp"
#include "prediction_report.hpp"
#include "prediction_targets.hpp"
#include "runtime_plot.hpp"

namespace asr_pose_prediction::bench {
namespace {

using asr_common::cli::CommandLine;
using asr_common::cli::UsageError;

// A count option that must be at least `minimum`.
std::size_t count(const CommandLine& options, const std::string& name, std::size_t fallback,
                  std::size_t minimum) {
  const long long value = options.integer(name, static_cast<long long>(fallback));
  if (value < static_cast<long long>(minimum))
    throw UsageError{"--" + name + " must be at least " + std::to_string(minimum)};
  return static_cast<std::size_t>(value);
}

PredictionBenchmarkSettings settingsFrom(const CommandLine& options) {
  PredictionBenchmarkSettings settings;
  settings.samples = count(options, "samples", settings.samples, 1);
  settings.accuracy_samples = count(options, "accuracy-samples", settings.accuracy_samples, 1);
  settings.timing_sets = count(options, "timing-sets", settings.timing_sets, 1);
  settings.accuracy_sets = count(options, "accuracy-sets", settings.accuracy_sets, 0);
  settings.repetitions = static_cast<int>(count(options, "repetitions", settings.repetitions, 1));
  const long long seed = options.integer("seed", settings.seed);
  if (seed > std::numeric_limits<std::uint32_t>::max())
    throw UsageError{"--seed must be below 2^32"};
  settings.seed = static_cast<std::uint32_t>(seed);
  return settings;
}

}  // namespace

int runPredictionBenchmark(const std::vector<std::string>& arguments) {
  const CommandLine options(arguments,
                            {"recordings", "plot", "samples", "accuracy-samples", "timing-sets",
                             "accuracy-sets", "repetitions", "seed"},
                            {"json", "no-synthetic", "no-accuracy"});
  const PredictionBenchmarkSettings settings = settingsFrom(options);
  if (options.has("plot") && options.flag("no-synthetic"))
    throw UsageError{"--plot draws the synthetic runtimes, which --no-synthetic leaves out"};
  std::ostream& progress = std::cerr;

  std::vector<RuntimeRow> kitchen_rows;
  std::vector<AccuracyRow> accuracy_rows;
  const std::optional<std::string> recordings = asr_common::cli::benchmarkRecordings(
      options, ASR_RECORDINGS_DIR, "asr_prediction_bench", progress);
  const bool have_recordings = recordings.has_value();
  if (have_recordings) {
    progress << "kitchen scenes from " << *recordings << ": runtime\n";
    kitchen_rows = benchmarkKitchenRuntime(*recordings, settings, progress);
    if (!options.flag("no-accuracy")) {
      progress << "kitchen scenes: leave-one-out accuracy\n";
      accuracy_rows = benchmarkKitchenAccuracy(*recordings, settings, progress);
    }
  }
  std::vector<RuntimeRow> synthetic_rows;
  if (!options.flag("no-synthetic")) {
    progress << "synthetic scenes: runtime (objects per step count)\n";
    synthetic_rows = benchmarkSyntheticRuntime(settings, progress);
  }
  std::vector<AccuracyRow> combined;
  if (!accuracy_rows.empty()) {
    for (bool held_out : {false, true}) {
      for (const char* topology : {"star", "complete"})
        combined.push_back(combinedAccuracy(accuracy_rows, topology, held_out));
    }
  }
  const std::vector<asr_common::cli::Target> targets =
      checkPredictionTargets(synthetic_rows, combined);

  if (options.flag("json")) {
    nlohmann::ordered_json json;
    json["kitchen_runtime"] = runtimeRowsToJson(kitchen_rows);
    json["synthetic_runtime"] = runtimeRowsToJson(synthetic_rows);
    json["accuracy"] = accuracyRowsToJson(accuracy_rows);
    json["accuracy_overall"] = accuracyRowsToJson(combined);
    json["targets"] = targetsToJson(targets);
    std::cout << json.dump(2) << "\n";
  } else {
    std::cout << "\n";
    if (have_recordings) {
      printKitchenRuntimeTable(std::cout, kitchen_rows, settings);
      std::cout << "\n";
    } else {
      std::cout << "Kitchen scenes: skipped, recordings folder not found\n\n";
    }
    if (!synthetic_rows.empty()) {
      printSyntheticRuntimeTable(std::cout, synthetic_rows, settings);
      std::cout << "\n";
    }
    if (!accuracy_rows.empty()) {
      printAccuracyTable(std::cout, accuracy_rows, combined, settings);
      std::cout << "\n";
    }
    asr_common::cli::printTargets(std::cout, targets);
  }
  if (options.has("plot")) {
    plotSyntheticRuntime(synthetic_rows, options.required("plot"));
    progress << "runtime plot written to " << options.required("plot") << "\n";
  }
  return 0;
}

}  // namespace asr_pose_prediction::bench
