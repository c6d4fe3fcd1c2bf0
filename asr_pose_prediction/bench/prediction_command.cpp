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
  return static_cast<std::size_t>(options.integer(name, static_cast<long long>(fallback),
                                                  static_cast<long long>(minimum), 100000000));
}

PredictionBenchmarkSettings settingsFrom(const CommandLine& options) {
  PredictionBenchmarkSettings settings;
  settings.samples = count(options, "samples", settings.samples, 1);
  settings.accuracy_samples = count(options, "accuracy-samples", settings.accuracy_samples, 1);
  settings.timing_sets = count(options, "timing-sets", settings.timing_sets, 1);
  settings.accuracy_sets = count(options, "accuracy-sets", settings.accuracy_sets, 0);
  settings.repetitions = static_cast<int>(count(options, "repetitions", settings.repetitions, 1));
  settings.seed = static_cast<std::uint32_t>(
      options.integer("seed", settings.seed, 0, std::numeric_limits<std::uint32_t>::max()));
  return settings;
}

// What one run measured.
struct Measured {
  bool have_recordings = false;
  std::vector<RuntimeRow> kitchen_rows;
  std::vector<AccuracyRow> accuracy_rows;
  std::vector<RuntimeRow> synthetic_rows;
  std::vector<AccuracyRow> combined;  // accuracy over all scenes, per topology and held-out
};

Measured measure(const CommandLine& options, const PredictionBenchmarkSettings& settings,
                 std::ostream& progress) {
  Measured measured;
  const std::optional<std::string> recordings = asr_common::cli::benchmarkRecordings(
      options, ASR_RECORDINGS_DIR, "asr_prediction_bench", progress);
  measured.have_recordings = recordings.has_value();
  if (recordings) {
    progress << "kitchen scenes from " << *recordings << ": runtime\n";
    measured.kitchen_rows = benchmarkKitchenRuntime(*recordings, settings, progress);
    if (!options.flag("no-accuracy")) {
      progress << "kitchen scenes: leave-one-out accuracy\n";
      measured.accuracy_rows = benchmarkKitchenAccuracy(*recordings, settings, progress);
    }
  }
  if (!options.flag("no-synthetic")) {
    progress << "synthetic scenes: runtime (objects per step count)\n";
    measured.synthetic_rows = benchmarkSyntheticRuntime(settings, progress);
  }
  if (!measured.accuracy_rows.empty()) {
    for (bool held_out : {false, true}) {
      for (const char* topology : {"star", "complete"})
        measured.combined.push_back(combinedAccuracy(measured.accuracy_rows, topology, held_out));
    }
  }
  return measured;
}

void printJson(const Measured& measured, const std::vector<asr_common::cli::Target>& targets) {
  nlohmann::ordered_json json;
  json["kitchen_runtime"] = runtimeRowsToJson(measured.kitchen_rows);
  json["synthetic_runtime"] = runtimeRowsToJson(measured.synthetic_rows);
  json["accuracy"] = accuracyRowsToJson(measured.accuracy_rows);
  json["accuracy_overall"] = accuracyRowsToJson(measured.combined);
  json["targets"] = targetsToJson(targets);
  std::cout << json.dump(2) << "\n";
}

void printTables(const Measured& measured, const PredictionBenchmarkSettings& settings,
                 const std::vector<asr_common::cli::Target>& targets) {
  std::cout << "\n";
  if (measured.have_recordings) {
    printKitchenRuntimeTable(std::cout, measured.kitchen_rows, settings);
    std::cout << "\n";
  } else {
    std::cout << "Kitchen scenes: skipped, recordings folder not found\n\n";
  }
  if (!measured.synthetic_rows.empty()) {
    printSyntheticRuntimeTable(std::cout, measured.synthetic_rows, settings);
    std::cout << "\n";
  }
  if (!measured.accuracy_rows.empty()) {
    printAccuracyTable(std::cout, measured.accuracy_rows, measured.combined, settings);
    std::cout << "\n";
  }
  asr_common::cli::printTargets(std::cout, targets);
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

  const Measured measured = measure(options, settings, progress);
  const std::vector<asr_common::cli::Target> targets =
      checkPredictionTargets(measured.synthetic_rows, measured.combined);
  if (options.flag("json"))
    printJson(measured, targets);
  else
    printTables(measured, settings, targets);
  if (options.has("plot")) {
    plotSyntheticRuntime(measured.synthetic_rows, options.required("plot"));
    progress << "runtime plot written to " << options.required("plot") << "\n";
  }
  return 0;
}

}  // namespace asr_pose_prediction::bench
