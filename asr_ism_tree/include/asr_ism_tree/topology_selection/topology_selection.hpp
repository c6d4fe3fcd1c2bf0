#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "asr_ism/demonstration.hpp"
#include "asr_ism/ism_recognizer.hpp"
#include "asr_ism_tree/relation_topology.hpp"
#include "asr_ism_tree/topology_selection/test_configurations.hpp"
#include "asr_ism_tree/topology_selection/topology_evaluation.hpp"

namespace asr_ism_tree {

enum class TopologySearchMethod { kHillClimbing, kSimulatedAnnealing };

/// The ranges tools and nodes accept for the options below: far beyond useful values (the paper
/// uses hundreds of tests and evaluations), small enough to finish and fit in memory.
constexpr long long kMaxTestCount = 100000;
constexpr long long kMaxEvaluations = 1000000;
constexpr long long kMaxTreeHeightOption = 1000;
constexpr long long kMaxThreads = 4096;
constexpr long long kMaxSeed = 4294967295LL;  // std::uint32_t

struct TopologySelectionOptions {
  std::size_t test_count = 600;  // test configurations generated (valid + invalid)
  std::uint32_t seed = 1;
  // A false positive makes the robot act on a scene that is not there, while a millisecond more
  // of recognition is rarely noticed next to camera moves of seconds: errors weigh more.
  double alpha = 10.0;  // weight of normalised errors (false positives + valid rejected)
  double beta = 1.0;    // weight of normalised work (avgDur) in the cost
  /// > 0: the recognition time budget in ms per configuration. It is converted into a work
  /// budget (comparisons) by the time per comparison measured on the star and complete trees,
  /// and topologies above it lose to every topology within it (see TopologyCost); if the chosen
  /// tree, timed alone, misses it, it is converted again by that tree's time per comparison.
  /// The search stays deterministic for a given conversion; the conversion depends on the
  /// machine.
  double max_duration_ms = 0.0;
  /// > 0: the time of one comparison in ms, used instead of timing the trees, so that the
  /// conversion of max_duration_ms, and the result, do not depend on the machine or its load
  /// (tests; a machine measured before). Every measure's mean_ms is then mean_work times this.
  double ms_per_comparison = 0.0;
  double threshold = 0.99;  // confidence at which a configuration counts as recognised
  int max_tree_height = 0;  // < 1: no limit
  unsigned threads = 0;     // 0: all cores
  asr_ism::IsmRecognitionParameters parameters;
  TopologySearchMethod method = TopologySearchMethod::kHillClimbing;
  /// The search stops after evaluating this many distinct topologies (stars and the complete
  /// topology included), or earlier when it cannot improve any more.
  std::size_t max_evaluations = 160;
  /// Neighbours are evaluated in parallel batches of this size, in a seeded random order; hill
  /// climbing takes the best of the first batch that improves, annealing the first accepted.
  /// Not tied to the thread count, so that the result does not depend on it.
  std::size_t batch_size = 8;
  /// Hill climbing: new starts after a local optimum, while evaluations are left: the best star
  /// grown by the relations the invalid configurations break (see RelationViolations) and the
  /// complete topology, unless the search started there, then the best topology so far with
  /// random relations exchanged.
  std::size_t restarts = 3;
  /// Simulated annealing: the start temperature in cost units and its factor per step.
  double start_temperature = 0.2;
  double cooling = 0.9;
  /// Start from this topology instead of the best star (must be connected).
  const RelationTopology* start = nullptr;
};

struct TopologySelectionProgress {
  std::size_t evaluated = 0;
  std::size_t max_evaluations = 0;
  double current_cost = 0.0;
  double best_cost = 0.0;
  double seconds_elapsed = 0.0;
  double seconds_left_estimate = 0.0;
};

/// The measures of the star, optimised and complete topologies are timed alone, in the fastest
/// of three passes over the test configurations.
struct TopologySelectionResult {
  RelationTopology topology;  // the optimised topology
  TopologyMeasures measures;  // and how it does
  double cost = 0.0;
  RelationTopology star;  // the star that normalises the cost (centre by chooseStarCenter)
  TopologyMeasures star_measures;
  TopologyMeasures complete_measures;
  std::size_t evaluated = 0;   // distinct topologies evaluated
  double max_mean_work = 0.0;  // the work budget max_duration_ms was converted to (0: none)
  TestConfigurations tests;
};

/// Relation Topology Selection: a local search over connected topologies of the demonstration's
/// objects for one whose tree has few false positives (numFPs) and little recognition work,
/// by the cost alpha * normalised errors + beta * normalised work (see TopologyCost). Starts
/// from the cheapest of the stars (every object tried as centre) and the complete topology, or
/// from options.start; neighbours add, remove or exchange one relation (topologyNeighbours);
/// every topology is evaluated at most once, in parallel batches on `threads` threads, and the
/// result is the cheapest evaluated. Deterministic for a seed: the cost uses the
/// machine-independent work, never the wall-clock time, and results do not depend on the thread
/// count (with a time budget: for a given conversion of it into work). `tests`, if given,
/// replaces generating test configurations. Throws InputError for bad options (0 tests, negative
/// weights) or a demonstration of fewer than two objects.
TopologySelectionResult selectTopology(
    const asr_ism::Demonstration& demonstration, const TopologySelectionOptions& options,
    const std::function<void(const TopologySelectionProgress&)>& progress = {},
    const TestConfigurations* tests = nullptr);

}  // namespace asr_ism_tree
