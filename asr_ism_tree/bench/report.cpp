#include "report.hpp"

#include <cstdio>
#include <ostream>
#include <string>

namespace asr_ism_tree::bench {
namespace {

// printf-style formatting into a string, for fixed-width table columns.
template <typename... Values>
std::string format(const char* pattern, Values... values) {
  char buffer[512];
  std::snprintf(buffer, sizeof(buffer), pattern, values...);
  return buffer;
}

std::string passesNote(const BenchmarkSettings& settings) {
  return "each configuration recognised in up to " + std::to_string(settings.max_passes) +
         " passes (no new pass after " + format("%.0f", settings.pass_budget_ms / 1000.0) +
         " s), its fastest time kept; " + std::to_string(settings.threads) + " thread(s)";
}

}  // namespace

void printSceneTable(std::ostream& out, const std::vector<SceneRow>& rows,
                     const BenchmarkSettings& settings) {
  out << "Kitchen scenes: recognition of every recorded set with the scene's own tree\n"
      << "(bin 0.1 m, 30 deg; learn_ms = tree generation + storing it in a fresh SQLite file, "
         "fastest of "
      << settings.learn_repetitions << ";\n " << passesNote(settings)
      << ";\n recognised = share of sets with confidence >= 0.99; missing-one = mean best "
         "confidence with one object left out,\n over every object of "
      << (settings.missing_one_sets == 0
              ? std::string("every set")
              : "up to " + std::to_string(settings.missing_one_sets) + " evenly spaced sets")
      << ")\n\n";
  out << format("%-17s %-8s %4s %4s %4s %3s %6s %8s %9s %8s %6s %10s %11s  %s\n", "scene",
                "topology", "objs", "sets", "isms", "h", "votes", "learn_ms", "median_ms", "max_ms",
                "passes", "recognised", "missing-one", "star centre");
  for (const SceneRow& row : rows) {
    const std::string line =
        format("%-17s %-8s %4zu %4zu %4zu %3d %6zu %8.2f %9.3f %8.3f %6d %10.3f %11.4f  %s",
               row.scene.c_str(), row.topology.c_str(), row.objects, row.sets, row.isms, row.height,
               row.votes, row.learn_ms, row.recog_median_ms, row.recog_max_ms, row.passes,
               row.recognised_fraction, row.missing_one_confidence, row.star_center.c_str());
    out << line.substr(0, line.find_last_not_of(' ') + 1) << "\n";
  }
}

void printSyntheticTable(std::ostream& out, const std::vector<SyntheticRow>& rows,
                         const BenchmarkSettings& settings) {
  out << "Synthetic scaling: complete topology, makeSyntheticDemonstration(objects, steps, seed "
      << settings.synthetic_seed << ")\n(recognition of up to " << settings.synthetic_configurations
      << " evenly spaced own steps; " << passesNote(settings) << ")\n\n";
  out << format("%4s %5s %4s %3s %6s %9s %7s %9s %8s %6s %10s\n", "objs", "steps", "isms", "h",
                "votes", "learn_ms", "configs", "median_ms", "max_ms", "passes", "recognised");
  for (const SyntheticRow& row : rows) {
    out << format("%4zu %5zu %4zu %3d %6zu %9.2f %7zu %9.3f %8.3f %6d %10.3f\n", row.objects,
                  row.steps, row.isms, row.height, row.votes, row.learn_ms, row.configurations,
                  row.recog_median_ms, row.recog_max_ms, row.passes, row.recognised_fraction);
  }
}

nlohmann::ordered_json sceneRowsToJson(const std::vector<SceneRow>& rows) {
  nlohmann::ordered_json array = nlohmann::ordered_json::array();
  for (const SceneRow& row : rows) {
    array.push_back({{"scene", row.scene},
                     {"topology", row.topology},
                     {"objects", row.objects},
                     {"sets", row.sets},
                     {"isms", row.isms},
                     {"height", row.height},
                     {"votes", row.votes},
                     {"learn_ms", row.learn_ms},
                     {"recog_median_ms", row.recog_median_ms},
                     {"recog_max_ms", row.recog_max_ms},
                     {"recognised_fraction", row.recognised_fraction},
                     {"missing_one_confidence", row.missing_one_confidence}});
  }
  return array;
}

nlohmann::ordered_json syntheticRowsToJson(const std::vector<SyntheticRow>& rows) {
  nlohmann::ordered_json array = nlohmann::ordered_json::array();
  for (const SyntheticRow& row : rows) {
    array.push_back({{"objects", row.objects},
                     {"steps", row.steps},
                     {"isms", row.isms},
                     {"height", row.height},
                     {"votes", row.votes},
                     {"learn_ms", row.learn_ms},
                     {"configurations", row.configurations},
                     {"recog_median_ms", row.recog_median_ms},
                     {"recog_max_ms", row.recog_max_ms},
                     {"recognised_fraction", row.recognised_fraction}});
  }
  return array;
}

}  // namespace asr_ism_tree::bench
