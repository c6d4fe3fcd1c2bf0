#include "clutter_benchmark.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ostream>

#include "asr_ism_tree/tree_recognizer.hpp"

namespace asr_ism_tree::bench {
namespace {

constexpr double kStopAfterMs = 30000.0;
// Best confidences within this are the same (rounding of sums of similarities).
constexpr double kSameBest = 1e-9;

double millisecondsOf(const TreeRecognizer& recognizer, const asr_common::Configuration& input,
                      std::vector<SceneInstance>& instances,
                      TreeRecognitionStats* stats = nullptr) {
  const auto start = std::chrono::steady_clock::now();
  instances = recognizer.recognize(input, stats);
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

double bestConfidence(const std::vector<SceneInstance>& instances) {
  return instances.empty() ? 0.0 : instances.front().confidence;
}

}  // namespace

std::vector<std::size_t> clutterSizes() {
  return {100, 250, 500, 1000, 2000, 5000, 10000};
}

std::size_t exhaustiveUpTo(const std::string& topology) {
  return topology == "star" ? 500 : 2000;
}

namespace {

// The series with the recorded set first (compared with the exhaustive search where that takes
// seconds) or without it (every copy jittered).
std::vector<ClutterRow> benchmarkSeries(const std::string& recordings,
                                        const BenchmarkSettings& settings, bool recorded_first,
                                        std::ostream& progress) {
  const asr_ism::Demonstration demonstration = clutterDemonstration(recordings);
  const asr_common::Configuration recorded = demonstration.configuration(kClutterRecordedSet);
  std::vector<ClutterRow> rows;
  for (const auto& [topology, tree] : clutterTrees(demonstration)) {
    TreeRecognitionParameters parameters;
    parameters.max_estimates = clutterSizes().back();
    if (settings.exact_search_max_votes > 0)
      parameters.exact_search_max_votes = settings.exact_search_max_votes;
    const TreeRecognizer recognizer(tree, parameters);
    const TreeRecognizer exhaustive(tree, exhaustiveClutterParameters(clutterSizes().back()));
    bool too_slow = false;
    progress << "  clutter" << (recorded_first ? "" : " without its recorded set") << ", "
             << topology << ":" << std::flush;
    for (std::size_t estimates : clutterSizes()) {
      ClutterRow row;
      row.topology = topology;
      row.estimates = estimates;
      if (!too_slow) {
        const auto input =
            clutteredCopies(recorded, estimates, settings.synthetic_seed, recorded_first);
        std::vector<SceneInstance> instances;
        TreeRecognitionStats stats;
        row.milliseconds = millisecondsOf(recognizer, input, instances, &stats);
        row.merged = stats.merged_estimates;
        row.search_complete = !instances.empty() && instances.front().search_complete;
        for (int again = 1; again < 3 && row.milliseconds < 2000.0; ++again)
          row.milliseconds =
              std::min(row.milliseconds, millisecondsOf(recognizer, input, instances));
        row.run = true;
        row.instances = instances.size();
        row.best_confidence = bestConfidence(instances);
        if (recorded_first && estimates <= exhaustiveUpTo(topology)) {
          TreeRecognitionStats exhaustive_stats;
          row.exhaustive_milliseconds =
              millisecondsOf(exhaustive, input, instances, &exhaustive_stats);
          row.exhaustive_best_confidence = bestConfidence(instances);
          row.exhaustive_given_up = exhaustive_stats.exact_searches_given_up > 0;
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

}  // namespace

std::vector<ClutterRow> benchmarkClutter(const std::string& recordings,
                                         const BenchmarkSettings& settings,
                                         std::ostream& progress) {
  return benchmarkSeries(recordings, settings, true, progress);
}

std::vector<ClutterRow> benchmarkJitteredClutter(const std::string& recordings,
                                                 const BenchmarkSettings& settings,
                                                 std::ostream& progress) {
  return benchmarkSeries(recordings, settings, false, progress);
}

void printJitteredClutterTable(std::ostream& out, const std::vector<ClutterRow>& rows) {
  out << "Clutter without its recorded set: every copy of gedeck set " << kClutterRecordedSet
      << " jittered\n(no repeat fits exactly; *: search_complete false, a search ran out of its "
         "work limits,\n the best found before it stands; docs/recognition.md compares these "
         "with the code of 2026-11-23)\n";
  out << "topology  estimates     kept        ms  instances  best confidence\n";
  char line[200];
  for (const ClutterRow& row : rows) {
    std::snprintf(line, sizeof line, "%-8s  %9zu  %7zu  %8.1f  %9zu  %15.4f%s\n",
                  row.topology.c_str(), row.estimates, row.estimates - row.merged, row.milliseconds,
                  row.instances, row.best_confidence, row.search_complete ? "" : "*");
    out << line;
  }
}

std::string comparedWithExhaustive(const ClutterRow& row) {
  if (row.exhaustive_best_confidence < 0.0)
    return "";
  const double shortfall = row.exhaustive_best_confidence - row.best_confidence;
  char text[64];
  if (std::abs(shortfall) <= kSameBest)
    std::snprintf(text, sizeof text, "same");
  else if (shortfall > 0.0)
    std::snprintf(text, sizeof text, "lower by %.2g", shortfall);
  else
    std::snprintf(text, sizeof text, "higher by %.2g", -shortfall);
  return std::string(text) + (row.exhaustive_given_up ? " (exhaustive gave up)" : "");
}

void printClutterTable(std::ostream& out, const std::vector<ClutterRow>& rows) {
  out << "Clutter: gedeck set " << kClutterRecordedSet
      << " repeated with 2 cm / 3 deg jitter (all estimates of the scene's types)\n";
  out << "(repeated detections merged; *: search_complete false, a search ran out of its "
         "work limits,\n"
      << " the best found before it stands; exhaustive: every repeat enters the search, as before\n"
      << " they were merged, up to " << exhaustiveUpTo("star") << " (star) and "
      << exhaustiveUpTo("complete") << " (complete) estimates; vs exhaustive: the\n"
      << " best against the exhaustive best at 1e-9)\n";
  out << "topology  estimates     kept        ms  instances  best confidence  exhaustive best"
         "  exhaustive ms  vs exhaustive\n";
  char line[200];
  for (const ClutterRow& row : rows) {
    if (row.run) {
      std::snprintf(line, sizeof line, "%-8s  %9zu  %7zu  %8.1f  %9zu  %15.3f",
                    row.topology.c_str(), row.estimates, row.estimates - row.merged,
                    row.milliseconds, row.instances, row.best_confidence);
      out << line << (row.search_complete ? " " : "*");
      if (row.exhaustive_best_confidence >= 0.0) {
        std::snprintf(line, sizeof line, " %15.3f  %13.1f  %s", row.exhaustive_best_confidence,
                      row.exhaustive_milliseconds, comparedWithExhaustive(row).c_str());
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
