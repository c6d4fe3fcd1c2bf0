#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "asr_ism_tree/topology_selection/topology_selection.hpp"

namespace asr_ism_tree::bench {

/// The paper's figures for one kitchen scene (its table "Performance of ISM trees learned for
/// scene categories in our kitchen"): relations, numFPs in percent and avgDur in seconds for the
/// star, optimised and complete topologies.
struct PaperTopologyRow {
  const char* scene;
  int relations[3];
  double false_positives_percent[3];
  double duration_s[3];
};
const std::vector<PaperTopologyRow>& paperTopologyRows();

/// One scene of the table: our star, optimised and complete trees on the same tests.
struct TopologyTableRow {
  std::string scene;
  std::size_t steps = 0;
  std::size_t objects = 0;
  std::size_t valid_tests = 0;
  std::size_t invalid_tests = 0;
  TopologyMeasures measures[3];  // star, optimised, complete
  std::size_t evaluated = 0;
  double seconds = 0.0;
  std::string topology;  // the optimised relations, "A-B A-C ..."
  const PaperTopologyRow* paper = nullptr;
};

/// Relation topology selection for every kitchen scene in `recordings` with `options`.
std::vector<TopologyTableRow> benchmarkTopologies(const std::string& recordings,
                                                  const std::vector<std::string>& scenes,
                                                  const TopologySelectionOptions& options,
                                                  std::ostream& progress);

/// One synthetic point of the runtime figure: recognition time of the optimised tree.
struct TopologyRuntimePoint {
  std::size_t objects = 0;
  std::size_t steps = 0;
  double mean_ms = 0.0;
  std::size_t relations = 0;
};

/// Optimised trees of synthetic demonstrations (2..max_objects objects x 100, 200, 400, 1000
/// steps), selected with `options`, timed on their test configurations.
std::vector<TopologyRuntimePoint> benchmarkSyntheticTopologies(
    const TopologySelectionOptions& options, std::size_t max_objects, std::ostream& progress);

}  // namespace asr_ism_tree::bench
