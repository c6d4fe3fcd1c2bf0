#include "clutter_benchmark.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ostream>

#include "asr_ism/portable_random.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism_tree/star_center.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"

namespace asr_ism_tree::bench {
namespace {

constexpr double kStopAfterMs = 30000.0;
constexpr std::size_t kRecordedSet = 5;

double millisecondsOf(const TreeRecognizer& recognizer, const asr_common::Configuration& input,
                      std::vector<SceneInstance>& instances,
                      TreeRecognitionStats* stats = nullptr) {
  const auto start = std::chrono::steady_clock::now();
  instances = recognizer.recognize(input, stats);
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

std::vector<std::size_t> clutterSizes() {
  return {100, 250, 500, 1000, 2000, 5000, 10000};
}

asr_common::Configuration clutteredCopies(const asr_common::Configuration& recorded,
                                          std::size_t estimates, std::uint32_t seed) {
  asr_ism::PortableRandom random(seed);
  asr_common::Configuration configuration;
  for (std::size_t i = 0; i < estimates; ++i) {
    asr_common::ObjectEstimate estimate = recorded[i % recorded.size()];
    if (i >= recorded.size()) {
      const Eigen::Vector3d shift(random.gaussian(), random.gaussian(), random.gaussian());
      const Eigen::Vector3d axis(random.gaussian(), random.gaussian(), random.gaussian());
      estimate.pose.position += 0.02 * shift;
      estimate.pose.orientation = (estimate.pose.orientation *
                                   Eigen::Quaterniond(Eigen::AngleAxisd(
                                       3.0 * M_PI / 180.0 * random.gaussian(), axis.normalized())))
                                      .normalized();
    }
    configuration.push_back(estimate);
  }
  return configuration;
}

std::vector<ClutterRow> benchmarkClutter(const std::string& recordings,
                                         const BenchmarkSettings& settings,
                                         std::ostream& progress) {
  const asr_ism::Demonstration demonstration =
      asr_ism::sqlite::readDemonstration(recordings + "/story_1.sqlite", "gedeck");
  const auto& objects = demonstration.objects();
  const std::pair<std::string, IsmTree> trees[] = {
      {"star",
       generateIsmTree(demonstration,
                       RelationTopology::star(objects, chooseStarCenter(demonstration)), {})},
      {"complete", generateIsmTree(demonstration, RelationTopology::complete(objects), {})}};
  const asr_common::Configuration recorded = demonstration.configuration(kRecordedSet);
  std::vector<ClutterRow> rows;
  for (const auto& [topology, tree] : trees) {
    TreeRecognitionParameters parameters;
    parameters.max_estimates = clutterSizes().back();
    if (settings.exact_search_max_votes > 0)
      parameters.exact_search_max_votes = settings.exact_search_max_votes;
    const TreeRecognizer recognizer(tree, parameters);
    parameters.merge_repeated_detections = false;
    const TreeRecognizer exhaustive(tree, parameters);
    bool too_slow = false;
    progress << "  clutter, " << topology << ":" << std::flush;
    for (std::size_t estimates : clutterSizes()) {
      ClutterRow row;
      row.topology = topology;
      row.estimates = estimates;
      if (!too_slow) {
        const auto input = clutteredCopies(recorded, estimates, settings.synthetic_seed);
        std::vector<SceneInstance> instances;
        TreeRecognitionStats stats;
        row.milliseconds = millisecondsOf(recognizer, input, instances, &stats);
        row.merged = stats.merged_estimates;
        row.repeat_search_given_up = stats.repeat_searches_given_up > 0;
        for (int again = 1; again < 3 && row.milliseconds < 2000.0; ++again)
          row.milliseconds =
              std::min(row.milliseconds, millisecondsOf(recognizer, input, instances));
        row.run = true;
        row.instances = instances.size();
        row.best_confidence = instances.empty() ? 0.0 : instances.front().confidence;
        if (estimates == clutterSizes().front()) {
          millisecondsOf(exhaustive, input, instances);
          row.exhaustive_best_confidence = instances.empty() ? 0.0 : instances.front().confidence;
        }
        too_slow = row.milliseconds > kStopAfterMs;
        progress << " " << estimates << std::flush;
      }
      rows.push_back(row);
    }
    progress << "\n";
  }
  return rows;
}

void printClutterTable(std::ostream& out, const std::vector<ClutterRow>& rows) {
  out << "Clutter: gedeck set " << kRecordedSet
      << " repeated with 2 cm / 3 deg jitter (all estimates of the scene's types)\n";
  out << "(repeated detections merged; exhaustive: every repeat enters the search; *: the search\n"
      << " over every repeat ran out of its work limits, the best over the merged ones stands)\n";
  out << "topology  estimates     kept        ms  instances  best confidence  exhaustive best\n";
  char line[160];
  for (const ClutterRow& row : rows) {
    if (row.run) {
      std::snprintf(line, sizeof line, "%-8s  %9zu  %7zu  %8.1f  %9zu  %15.3f",
                    row.topology.c_str(), row.estimates, row.estimates - row.merged,
                    row.milliseconds, row.instances, row.best_confidence);
      out << line << (row.repeat_search_given_up ? "*" : " ");
      if (row.exhaustive_best_confidence >= 0.0) {
        std::snprintf(line, sizeof line, " %15.3f", row.exhaustive_best_confidence);
        out << line;
      }
      out << "\n";
    } else {
      std::snprintf(line, sizeof line,
                    "%-8s  %9zu  %7s  %8s  (not run: a smaller size took > %.0f s)\n",
                    row.topology.c_str(), row.estimates, "-", "-", kStopAfterMs / 1000.0);
      out << line;
    }
  }
}

}  // namespace asr_ism_tree::bench
