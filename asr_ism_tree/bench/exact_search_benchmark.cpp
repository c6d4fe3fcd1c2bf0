#include "exact_search_benchmark.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#include "asr_common/cli/command_line.hpp"
#include "asr_common/cli/recordings_folder.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism_tree/topology_selection/test_configurations.hpp"
#include "asr_ism_tree/topology_selection/topology_selection.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"

namespace asr_ism_tree::bench {
namespace {

constexpr std::uint32_t kSeed = 1;
constexpr double kThreshold = 0.99;

struct Timed {
  double milliseconds = 0.0;
  double best_confidence = 0.0;
  TreeRecognitionStats stats;
};

Timed recognise(const TreeRecognizer& recognizer, const asr_common::Configuration& input) {
  Timed timed;
  const auto start = std::chrono::steady_clock::now();
  const auto instances = recognizer.recognize(input, &timed.stats);
  timed.milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  timed.best_confidence = instances.empty() ? 0.0 : instances.front().confidence;
  return timed;
}

ExactSearchRow measureScene(const asr_ism::Demonstration& demonstration, std::size_t tests,
                            const TreeRecognitionParameters& parameters) {
  const IsmTree tree =
      generateIsmTree(demonstration, RelationTopology::complete(demonstration.objects()), {});
  const TestConfigurations configurations =
      generateTestConfigurations(demonstration, tree, tests, kSeed, kThreshold);
  const TreeRecognizer exact(tree, parameters);
  TreeRecognitionParameters first_only = parameters;
  first_only.exact_best = false;
  const TreeRecognizer first(tree, first_only);

  ExactSearchRow row;
  row.scene = demonstration.scene();
  for (const auto* group : {&configurations.valid, &configurations.invalid}) {
    for (const asr_common::Configuration& configuration : *group) {
      const Timed without = recognise(first, configuration);
      const Timed with = recognise(exact, configuration);
      ++row.configurations;
      row.first_mean_ms += without.milliseconds;
      row.first_max_ms = std::max(row.first_max_ms, without.milliseconds);
      row.exact_mean_ms += with.milliseconds;
      row.exact_max_ms = std::max(row.exact_max_ms, with.milliseconds);
      row.exact_max_comparisons =
          std::max(row.exact_max_comparisons, with.stats.exact_search_comparisons);
      row.given_up += with.stats.exact_searches_given_up > 0 ? 1 : 0;
      row.pose_gap_open += with.stats.pose_gaps_left_open > 0 ? 1 : 0;
      row.subset_searches += with.stats.object_subset_searches;
      row.subsets_cut += with.stats.object_subset_searches_cut > 0 ? 1 : 0;
      const double gain = with.best_confidence - without.best_confidence;
      row.improved += gain > 1e-9 ? 1 : 0;
      row.largest_gain = std::max(row.largest_gain, gain);
    }
  }
  if (row.configurations > 0) {
    row.first_mean_ms /= static_cast<double>(row.configurations);
    row.exact_mean_ms /= static_cast<double>(row.configurations);
  }
  return row;
}

}  // namespace

std::vector<ExactSearchRow> benchmarkExactSearch(const std::string& recordings,
                                                 const std::string& scene, std::size_t tests,
                                                 const TreeRecognitionParameters& parameters,
                                                 std::ostream& progress) {
  std::vector<ExactSearchRow> rows;
  for (const asr_common::cli::KitchenScene& kitchen_scene : asr_common::cli::kitchenScenes()) {
    if (!scene.empty() && scene != kitchen_scene.scene)
      continue;
    progress << "  " << kitchen_scene.scene << " ..." << std::flush;
    rows.push_back(measureScene(asr_ism::sqlite::readDemonstration(
                                    recordings + "/" + kitchen_scene.file, kitchen_scene.scene),
                                tests, parameters));
    progress << " done\n";
  }
  return rows;
}

void printExactSearchTable(std::ostream& out, const std::vector<ExactSearchRow>& rows) {
  out << "Exact search on topology selection's test configurations (complete trees)\n";
  out << "scene              configs  first mean/max ms   exact mean/max ms  max comparisons"
         "  given up  gap open  improved  largest gain  subsets  cut\n";
  char line[200];
  for (const ExactSearchRow& row : rows) {
    std::snprintf(
        line, sizeof line,
        "%-17s  %7zu  %8.2f %8.1f  %8.2f %8.1f  %15zu  %8zu  %8zu  %8zu  %12.4f  %7zu  %3zu\n",
        row.scene.c_str(), row.configurations, row.first_mean_ms, row.first_max_ms,
        row.exact_mean_ms, row.exact_max_ms, row.exact_max_comparisons, row.given_up,
        row.pose_gap_open, row.improved, row.largest_gain, row.subset_searches, row.subsets_cut);
    out << line;
  }
}

int runExactSearchCommand(const std::vector<std::string>& arguments) {
  const asr_common::cli::CommandLine options(
      arguments,
      {"recordings", "scene", "tests", "demo", "max-votes", "max-comparisons", "max-pose-steps",
       "diverse", "subsets"},
      {});
  TreeRecognitionParameters parameters;
  parameters.exact_search_max_votes = static_cast<std::size_t>(options.integer(
      "max-votes", static_cast<long long>(parameters.exact_search_max_votes), 1, 1LL << 40));
  parameters.exact_search_max_comparisons = static_cast<std::size_t>(options.integer(
      "max-comparisons", static_cast<long long>(parameters.exact_search_max_comparisons), 1,
      1LL << 50));
  parameters.exact_search_max_pose_steps = static_cast<std::size_t>(options.integer(
      "max-pose-steps", static_cast<long long>(parameters.exact_search_max_pose_steps), 0,
      1LL << 50));
  parameters.diverse_results_passed_up = static_cast<std::size_t>(options.integer(
      "diverse", static_cast<long long>(parameters.diverse_results_passed_up), 0, 1 << 20));
  parameters.object_subsets_max_work = static_cast<std::size_t>(options.integer(
      "subsets", static_cast<long long>(parameters.object_subsets_max_work), 0, 1LL << 50));
  const std::size_t tests =
      static_cast<std::size_t>(options.integer("tests", 200, 1, kMaxTestCount));
  const std::string scene = options.optional("scene", "");
  if (options.has("demo")) {
    const ExactSearchRow row = measureScene(
        asr_ism::sqlite::readDemonstration(options.required("demo"), options.required("scene")),
        tests, parameters);
    printExactSearchTable(std::cout, {row});
    return 0;
  }
  const auto recordings =
      asr_common::cli::benchmarkRecordings(options, ASR_RECORDINGS_DIR, "asr_bench", std::cerr);
  if (!recordings) {
    std::cout << "Exact search: skipped, recordings folder not found\n";
    return 0;
  }
  const std::vector<ExactSearchRow> rows =
      benchmarkExactSearch(*recordings, scene, tests, parameters, std::cerr);
  printExactSearchTable(std::cout, rows);
  return 0;
}

}  // namespace asr_ism_tree::bench
