#include "prediction_report.hpp"

#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

namespace asr_pose_prediction::bench {
namespace {

// printf-style formatting into a string, for fixed-width table columns.
template <typename... Values>
std::string format(const char* pattern, Values... values) {
  char buffer[512];
  std::snprintf(buffer, sizeof(buffer), pattern, values...);
  return buffer;
}

std::string timingNote(const PredictionBenchmarkSettings& settings) {
  return std::to_string(settings.samples) +
         " poses of every object of the scene from one instance (PosePredictor::predict, the "
         "instance's objects\n dropped so that all are predicted); each instance timed " +
         std::to_string(settings.repetitions) +
         " times, fastest kept; median and max over instances";
}

void printRuntimeRows(std::ostream& out, const std::vector<RuntimeRow>& rows) {
  out << format("%-17s %-8s %4s %5s %4s %2s %4s %6s %5s %9s %8s\n", "scene", "topology", "objs",
                "steps", "isms", "h", "path", "votes", "inst", "median_ms", "max_ms");
  for (const RuntimeRow& row : rows) {
    out << format("%-17s %-8s %4zu %5zu %4zu %2d %4zu %6zu %5zu %9.4f %8.4f\n", row.scene.c_str(),
                  row.topology.c_str(), row.objects, row.steps, row.isms, row.height,
                  row.longest_path, row.votes, row.instances, row.median_ms, row.max_ms);
  }
}

// A value of a distribution; an infinity (a case without an instance) as "none".
std::string value(double number, const char* pattern) {
  return std::isfinite(number) ? format(pattern, number) : std::string("none");
}

std::string distributionColumns(const std::vector<double>& values, const char* pattern) {
  const Distribution distribution = distributionOf(values);
  return format("%8s %8s %8s", value(distribution.median, pattern).c_str(),
                value(distribution.p90, pattern).c_str(), value(distribution.max, pattern).c_str());
}

void printAccuracyRow(std::ostream& out, const AccuracyRow& row) {
  out << format("%-17s %-8s %-8s %4zu %5zu %4zu  ", row.scene.c_str(), row.topology.c_str(),
                row.held_out ? "held-out" : "all sets", row.sets, row.cases, row.no_instance)
      << distributionColumns(row.distances_m, "%.4f") << "  "
      << distributionColumns(row.angles_at_nearest_deg, "%.2f") << "  "
      << distributionColumns(row.smallest_angles_deg, "%.2f") << "\n";
}

nlohmann::ordered_json distributionToJson(const std::vector<double>& values) {
  const Distribution distribution = distributionOf(values);
  nlohmann::ordered_json json;
  for (const auto& [key, number] : {std::pair<const char*, double>{"median", distribution.median},
                                    {"p90", distribution.p90},
                                    {"max", distribution.max}}) {
    json[key] = std::isfinite(number) ? nlohmann::ordered_json(number) : nlohmann::ordered_json();
  }
  return json;
}

}  // namespace

void printKitchenRuntimeTable(std::ostream& out, const std::vector<RuntimeRow>& rows,
                              const PredictionBenchmarkSettings& settings) {
  out << "Kitchen scenes: prediction runtime\n(" << timingNote(settings) << ";\n instances from "
      << settings.timing_sets
      << " evenly spaced recorded sets; path = ISMs on the longest prediction path)\n\n";
  printRuntimeRows(out, rows);
}

void printSyntheticRuntimeTable(std::ostream& out, const std::vector<RuntimeRow>& rows,
                                const PredictionBenchmarkSettings& settings) {
  out << "Synthetic scenes: prediction runtime, makeSyntheticDemonstration(objects, steps, seed "
      << settings.synthetic_seed << ")\n(" << timingNote(settings) << ";\n instances from "
      << settings.synthetic_configurations << " evenly spaced own steps)\n\n";
  printRuntimeRows(out, rows);
}

void printAccuracyTable(std::ostream& out, const std::vector<AccuracyRow>& rows,
                        const std::vector<AccuracyRow>& combined,
                        const PredictionBenchmarkSettings& settings) {
  out << "Kitchen scenes: leave-one-out accuracy of predicted poses\n(every object of "
      << (settings.accuracy_sets == 0
              ? std::string("every recorded set")
              : std::to_string(settings.accuracy_sets) + " evenly spaced recorded sets")
      << " left out, the rest recognised, " << settings.accuracy_samples
      << " poses of it predicted from the best instance;\n distance = true position to the "
         "nearest predicted position; angle@nearest = orientation error of that pose;\n min angle "
         "= smallest orientation error of any predicted pose; median, 90th percentile, max;\n "
         "none = no instance found without the object, counted as infinitely far;\n tree: "
         "'all sets' = learned from the whole demonstration, the set included (the issue's "
         "measure);\n 'held-out' = for each set a tree of the same topology learned from all "
         "other sets)\n\n";
  out << format("%-17s %-8s %-8s %4s %5s %4s  %-26s  %-26s  %-26s\n", "", "", "", "", "", "",
                "   distance_m", "   angle@nearest_deg", "   min_angle_deg")
      << format("%-17s %-8s %-8s %4s %5s %4s  %8s %8s %8s  %8s %8s %8s  %8s %8s %8s\n", "scene",
                "topology", "tree", "sets", "cases", "none", "median", "p90", "max", "median",
                "p90", "max", "median", "p90", "max");
  for (const AccuracyRow& row : rows)
    printAccuracyRow(out, row);
  for (const AccuracyRow& row : combined)
    printAccuracyRow(out, row);
}

nlohmann::ordered_json runtimeRowsToJson(const std::vector<RuntimeRow>& rows) {
  nlohmann::ordered_json array = nlohmann::ordered_json::array();
  for (const RuntimeRow& row : rows) {
    array.push_back({{"scene", row.scene},
                     {"topology", row.topology},
                     {"objects", row.objects},
                     {"steps", row.steps},
                     {"isms", row.isms},
                     {"height", row.height},
                     {"longest_path", row.longest_path},
                     {"votes", row.votes},
                     {"instances", row.instances},
                     {"samples", row.samples},
                     {"median_ms", row.median_ms},
                     {"max_ms", row.max_ms}});
  }
  return array;
}

nlohmann::ordered_json accuracyRowsToJson(const std::vector<AccuracyRow>& rows) {
  nlohmann::ordered_json array = nlohmann::ordered_json::array();
  for (const AccuracyRow& row : rows) {
    array.push_back({{"scene", row.scene},
                     {"topology", row.topology},
                     {"held_out", row.held_out},
                     {"sets", row.sets},
                     {"cases", row.cases},
                     {"no_instance", row.no_instance},
                     {"distance_m", distributionToJson(row.distances_m)},
                     {"angle_at_nearest_deg", distributionToJson(row.angles_at_nearest_deg)},
                     {"smallest_angle_deg", distributionToJson(row.smallest_angles_deg)}});
  }
  return array;
}

}  // namespace asr_pose_prediction::bench
