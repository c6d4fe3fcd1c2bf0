#include "topology_benchmark.hpp"

#include <algorithm>
#include <chrono>
#include <ostream>

#include "asr_common/cli/recordings_folder.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism/synthetic_demonstration.hpp"
#include "synthetic_benchmark.hpp"

namespace asr_ism_tree::bench {

const std::vector<PaperTopologyRow>& paperTopologyRows() {
  static const std::vector<PaperTopologyRow> rows = {
      {"gedeck", {7, 15, 28}, {38.56, 3.86, 0}, {0.044, 1.228, 7.558}},
      {"Gedeck_Ende", {7, 15, 28}, {19.59, 2.92, 0}, {0.196, 2.430, 8.772}},
      {"Gedeck_Schrank_2", {8, 15, 36}, {23.70, 8.09, 0}, {0.020, 0.140, 1.070}},
      {"Spuelkorb_3", {9, 9, 45}, {15.38, 0, 0}, {0.053, 0.060, 1.099}},
      {"Brot_Gedeck_2", {4, 4, 10}, {0, 0, 0}, {0.019, 0.019, 0.131}},
      {"Brot_Regal", {5, 7, 15}, {29.05, 6.70, 0}, {0.017, 0.042, 0.264}},
      {"Getraenke_Gedeck", {2, 2, 3}, {67.02, 67.02, 0}, {0.001, 0.001, 0.004}},
      {"Getraenke_Regal", {3, 3, 6}, {44.51, 11.54, 0}, {0.003, 0.008, 0.013}},
      {"Muesli_Gedeck", {3, 3, 6}, {33.67, 0, 0}, {0.002, 0.004, 0.012}},
      {"Muesli_Regal", {4, 7, 10}, {9.50, 1.68, 0}, {0.014, 0.053, 0.181}}};
  return rows;
}

namespace {

std::string relationsText(const RelationTopology& topology) {
  std::string text;
  for (const auto& [a, b] : topology.relations()) {
    text +=
        (text.empty() ? "" : " ") + topology.objects()[a].type + "-" + topology.objects()[b].type;
  }
  return text;
}

}  // namespace

std::vector<TopologyTableRow> benchmarkTopologies(const std::string& recordings,
                                                  const std::vector<std::string>& scenes,
                                                  const TopologySelectionOptions& options,
                                                  std::ostream& progress) {
  std::vector<TopologyTableRow> rows;
  for (const asr_common::cli::KitchenScene& kitchen : asr_common::cli::kitchenScenes()) {
    if (!scenes.empty() && std::find(scenes.begin(), scenes.end(), kitchen.scene) == scenes.end())
      continue;
    progress << "  " << kitchen.scene << ": " << std::flush;
    const auto start = std::chrono::steady_clock::now();
    const asr_ism::Demonstration demonstration =
        asr_ism::sqlite::readDemonstration(recordings + "/" + kitchen.file, kitchen.scene);
    const TopologySelectionResult result = selectTopology(demonstration, options);
    TopologyTableRow row;
    row.scene = kitchen.scene;
    row.steps = demonstration.stepCount();
    row.objects = demonstration.objectCount();
    row.valid_tests = result.tests.valid.size();
    row.invalid_tests = result.tests.invalid.size();
    row.measures[0] = result.star_measures;
    row.measures[1] = result.measures;
    row.measures[2] = result.complete_measures;
    row.evaluated = result.evaluated;
    row.topology = relationsText(result.topology);
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const PaperTopologyRow& paper : paperTopologyRows()) {
      if (row.scene == paper.scene)
        row.paper = &paper;
    }
    progress << result.evaluated << " topologies, " << row.seconds << " s\n";
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<TopologyRuntimePoint> benchmarkSyntheticTopologies(
    const TopologySelectionOptions& options, std::size_t max_objects, std::ostream& progress) {
  std::vector<TopologyRuntimePoint> points;
  for (std::size_t steps : syntheticStepCounts()) {
    progress << "  " << steps << " steps:" << std::flush;
    for (std::size_t objects = 2; objects <= max_objects; ++objects) {
      progress << " " << objects << std::flush;
      const asr_ism::Demonstration demonstration =
          asr_ism::makeSyntheticDemonstration(objects, steps, 1);
      const TopologySelectionResult result = selectTopology(demonstration, options);
      points.push_back({objects, steps, result.measures.mean_ms, result.topology.relationCount()});
    }
    progress << "\n";
  }
  return points;
}

}  // namespace asr_ism_tree::bench
