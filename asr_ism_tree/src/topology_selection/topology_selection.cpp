#include "asr_ism_tree/topology_selection/topology_selection.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <numeric>

#include "asr_common/input_error.hpp"
#include "asr_ism/portable_random.hpp"
#include "asr_ism/thread_pool.hpp"
#include "asr_ism_tree/star_center.hpp"
#include "asr_ism_tree/topology_selection/relation_violations.hpp"
#include "asr_ism_tree/topology_selection/topology_cost.hpp"
#include "asr_ism_tree/topology_selection/topology_neighbours.hpp"
#include "asr_ism_tree/tree_generation.hpp"

namespace asr_ism_tree {
namespace {

using asr_common::InputError;
using Clock = std::chrono::steady_clock;

// A relation counts as broken below 0.95 similarity: about 2 cm or 7 degrees off everything
// demonstrated at the default tolerances (10 cm, 30 degrees). Above it, one such relation among
// several already pulls a tree's confidence under the usual 0.99 threshold; on gedeck's test
// configurations this predicts the complete topology's 0 % and the star's false positives
// within 7 points, where requiring a relation to be outside the tolerances entirely predicted
// 75 % for the complete topology.
constexpr double kBrokenRelationDeficit = 0.05;

// Neighbours evaluated per batch while the climb is over the work budget.
constexpr std::size_t kOverBudgetBatchSize = 2;

// How often the chosen tree is timed alone and, if it misses the time budget, replaced.
constexpr int kBudgetRechecks = 10;

// Passes over the test configurations for a reported time; the fastest counts.
constexpr int kTimingPasses = 3;

// One character per object pair: the identity of a topology in the memo.
std::string keyOf(const RelationTopology& topology) {
  std::string key;
  for (std::size_t a = 0; a < topology.objectCount(); ++a) {
    for (std::size_t b = a + 1; b < topology.objectCount(); ++b)
      key += topology.hasRelation(a, b) ? '1' : '0';
  }
  return key;
}

struct Evaluated {
  RelationTopology topology;
  TopologyMeasures measures;
  double cost = std::numeric_limits<double>::infinity();
};

// Evaluates topologies at most once each, batches in parallel, and reports progress.
class Evaluator {
 public:
  Evaluator(const asr_ism::Demonstration& demonstration, const TestConfigurations& tests,
            const TopologySelectionOptions& options,
            const std::function<void(const TopologySelectionProgress&)>& progress)
      : demonstration_(demonstration),
        tests_(tests),
        options_(options),
        progress_(progress),
        pool_(options.threads),
        started_(Clock::now()) {}

  // From now on evaluations stop early once over this work budget (<= 0: none).
  void setWorkBudget(double max_mean_work) { max_mean_work_ = max_mean_work; }

  // Costs the topologies evaluated so far too.
  void setCost(const TopologyCost& cost) {
    cost_ = std::make_unique<TopologyCost>(cost);
    for (auto& [key, entry] : memo_)
      entry.cost = (*cost_)(entry.measures);
  }

  // Takes measures taken elsewhere as this topology's evaluation (costed once the cost is set).
  void remember(const RelationTopology& topology, const TopologyMeasures& measures) {
    Evaluated& entry = memo_[keyOf(topology)];
    entry.topology = topology;
    entry.measures = measures;
  }

  // The cheapest topology evaluated so far (ties: the first in key order), or nullptr.
  const Evaluated* cheapest() const {
    const Evaluated* found = nullptr;
    for (const auto& [key, entry] : memo_) {
      if (!found || entry.cost < found->cost)
        found = &entry;
    }
    return found;
  }

  bool budgetLeft() const { return memo_.size() < options_.max_evaluations; }
  std::size_t evaluated() const { return memo_.size(); }

  // Measures (and costs, once the cost is set) of every topology, evaluating the ones not seen
  // before in parallel. Topologies beyond the budget are left out of the result (nullptr).
  std::vector<const Evaluated*> evaluate(const std::vector<RelationTopology>& topologies) {
    std::vector<std::size_t> fresh;
    std::vector<std::string> keys;
    for (std::size_t i = 0; i < topologies.size(); ++i) {
      keys.push_back(keyOf(topologies[i]));
      if (!memo_.count(keys[i]) &&
          std::find_if(fresh.begin(), fresh.end(),
                       [&](std::size_t j) { return keys[j] == keys[i]; }) == fresh.end() &&
          memo_.size() + fresh.size() < options_.max_evaluations)
        fresh.push_back(i);
    }
    std::vector<TopologyMeasures> measured(fresh.size());
    pool_.parallelFor(fresh.size(), [&](std::size_t k) {
      measured[k] = evaluateTopology(demonstration_, topologies[fresh[k]], tests_,
                                     options_.parameters, options_.threshold, max_mean_work_);
    });
    for (std::size_t k = 0; k < fresh.size(); ++k) {
      Evaluated& entry = memo_[keys[fresh[k]]];
      entry.topology = topologies[fresh[k]];
      entry.measures = measured[k];
      if (cost_)
        entry.cost = (*cost_)(entry.measures);
    }
    std::vector<const Evaluated*> result;
    for (const std::string& key : keys) {
      const auto found = memo_.find(key);
      result.push_back(found == memo_.end() ? nullptr : &found->second);
    }
    return result;
  }

  void report(double current_cost, double best_cost) const {
    if (!progress_)
      return;
    TopologySelectionProgress progress;
    progress.evaluated = memo_.size();
    progress.max_evaluations = options_.max_evaluations;
    progress.current_cost = current_cost;
    progress.best_cost = best_cost;
    progress.seconds_elapsed = std::chrono::duration<double>(Clock::now() - started_).count();
    progress.seconds_left_estimate =
        memo_.empty()
            ? 0.0
            : progress.seconds_elapsed / memo_.size() *
                  (options_.max_evaluations - std::min(options_.max_evaluations, memo_.size()));
    progress_(progress);
  }

 private:
  const asr_ism::Demonstration& demonstration_;
  const TestConfigurations& tests_;
  const TopologySelectionOptions& options_;
  const std::function<void(const TopologySelectionProgress&)>& progress_;
  asr_ism::ThreadPool pool_;
  Clock::time_point started_;
  std::unique_ptr<TopologyCost> cost_;
  double max_mean_work_ = 0.0;
  std::map<std::string, Evaluated> memo_;
};

struct Candidate {
  RelationTopology topology;
  double cost = std::numeric_limits<double>::infinity();
};

// The neighbours, most promising first: by the number of invalid test configurations they are
// predicted to accept (RelationViolations), then by relation count (less work); ties in a seeded
// random order, additions and removals before the many exchanges. Without the prediction a climb
// through the r * (n(n-1)/2 - r) exchanges spends its budget on neighbours that change nothing.
std::vector<RelationTopology> orderedNeighbours(const RelationTopology& topology, int max_height,
                                                const RelationViolations& violations,
                                                asr_ism::PortableRandom& random) {
  std::vector<RelationTopology> neighbours = topologyNeighbours(topology, max_height);
  const auto exchanges = std::stable_partition(
      neighbours.begin(), neighbours.end(), [&](const RelationTopology& neighbour) {
        return neighbour.relationCount() != topology.relationCount();
      });
  auto shuffle = [&](auto begin, auto end) {
    for (auto i = end - begin; i > 1; --i)
      std::swap(begin[i - 1], begin[random.below(static_cast<std::uint32_t>(i))]);
  };
  shuffle(neighbours.begin(), exchanges);
  shuffle(exchanges, neighbours.end());
  std::vector<std::pair<std::size_t, std::size_t>> keys;
  for (const RelationTopology& neighbour : neighbours)
    keys.emplace_back(violations.predictedAccepted(neighbour), neighbour.relationCount());
  std::vector<std::size_t> order(neighbours.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
  std::vector<RelationTopology> ordered;
  ordered.reserve(neighbours.size());
  for (std::size_t i : order)
    ordered.push_back(std::move(neighbours[i]));
  return ordered;
}

// Steepest descent over batches: the best improving neighbour of the first batch that has one.
Candidate climb(Candidate current, Evaluator& evaluator, const TopologySelectionOptions& options,
                const RelationViolations& violations, std::size_t batch_size,
                asr_ism::PortableRandom& random, Candidate& best) {
  while (evaluator.budgetLeft()) {
    const std::vector<RelationTopology> neighbours =
        orderedNeighbours(current.topology, options.max_tree_height, violations, random);
    // Over the work budget the cost is the work alone, which nearly every removal lowers: small
    // batches then cross the over-budget region (e.g. down from a complete topology) in a
    // quarter of the evaluations.
    const std::size_t step = current.cost >= TopologyCost::kOverBudget
                                 ? std::min(kOverBudgetBatchSize, batch_size)
                                 : batch_size;
    bool moved = false;
    for (std::size_t first = 0; first < neighbours.size() && !moved; first += step) {
      const std::vector<RelationTopology> batch(
          neighbours.begin() + first,
          neighbours.begin() + std::min(neighbours.size(), first + step));
      const std::vector<const Evaluated*> results = evaluator.evaluate(batch);
      std::size_t chosen = batch.size();
      double chosen_cost = current.cost - 1e-12;
      for (std::size_t i = 0; i < batch.size(); ++i) {
        if (results[i] && results[i]->cost < chosen_cost) {
          chosen = i;
          chosen_cost = results[i]->cost;
        }
      }
      if (chosen < batch.size()) {
        current = {batch[chosen], chosen_cost};
        moved = true;
        if (current.cost < best.cost - 1e-12)
          best = current;
      }
      evaluator.report(current.cost, best.cost);
      if (!evaluator.budgetLeft())
        break;
    }
    if (!moved)
      break;  // a local optimum (or the budget is spent)
  }
  return current;
}

// A new start near the best: `count` of its relations exchanged for absent ones, kept connected.
RelationTopology perturbed(const RelationTopology& topology, std::size_t count, int max_height,
                           asr_ism::PortableRandom& random) {
  RelationTopology result = topology;
  for (std::size_t i = 0; i < count; ++i) {
    const std::vector<RelationTopology> neighbours = topologyNeighbours(result, max_height);
    if (neighbours.empty())
      break;
    result = neighbours[random.below(static_cast<std::uint32_t>(neighbours.size()))];
  }
  return result;
}

Candidate anneal(Candidate current, Evaluator& evaluator, const TopologySelectionOptions& options,
                 const RelationViolations& violations, std::size_t batch_size,
                 asr_ism::PortableRandom& random, Candidate& best) {
  double temperature = options.start_temperature;
  std::size_t stale = 0;
  while (evaluator.budgetLeft() && stale < 50) {
    const std::vector<RelationTopology> neighbours =
        orderedNeighbours(current.topology, options.max_tree_height, violations, random);
    if (neighbours.empty())
      break;
    // One batch per round, evaluated in parallel, then accepted or not in a fixed order.
    const std::size_t size = std::min(neighbours.size(), batch_size);
    const std::vector<RelationTopology> batch(neighbours.begin(), neighbours.begin() + size);
    const std::size_t before = evaluator.evaluated();
    const std::vector<const Evaluated*> results = evaluator.evaluate(batch);
    stale = evaluator.evaluated() == before ? stale + 1 : 0;
    for (std::size_t i = 0; i < batch.size(); ++i) {
      if (!results[i])
        continue;
      const double delta = results[i]->cost - current.cost;
      const double draw = random.uniform();
      if (delta < 0 || (temperature > 0 && draw < std::exp(-delta / temperature))) {
        current = {batch[i], results[i]->cost};
        if (current.cost < best.cost - 1e-12)
          best = current;
        break;
      }
    }
    temperature *= options.cooling;
    evaluator.report(current.cost, best.cost);
  }
  return current;
}

void checkSelectionInput(const asr_ism::Demonstration& demonstration,
                         const TopologySelectionOptions& options) {
  demonstration.validate("relation topology selection");
  const std::vector<ObjectKey>& objects = demonstration.objects();
  if (objects.size() < 2)
    throw InputError("scene '" + demonstration.scene() +
                     "': relation topology selection needs at least two objects");
  if (!(options.max_duration_ms >= 0.0) || !std::isfinite(options.max_duration_ms))
    throw InputError("the recognition time budget must be a finite number of ms >= 0 (got " +
                     std::to_string(options.max_duration_ms) + ")");
  if (options.max_evaluations < 2)
    throw InputError("relation topology selection needs at least 2 evaluations (got " +
                     std::to_string(options.max_evaluations) + ")");
  if (options.start) {
    options.start->requireConnected("the start topology");
    if (options.start->objects() != objects)
      throw InputError("the start topology's objects differ from those of scene '" +
                       demonstration.scene() + "'");
  }
}

// Times are taken on this thread, one topology after the other, in the least disturbed of a few
// passes: the wall-clock times of the parallel search include the other threads' contention,
// and on a shared machine a single pass varies by a third. Everything else is deterministic.
// With a given time per comparison (options.ms_per_comparison > 0) nothing is timed: one pass,
// and the time is the work times that.
TopologyMeasures fastestMeasures(const asr_ism::Demonstration& demonstration,
                                 const RelationTopology& topology, const TestConfigurations& tests,
                                 const TopologySelectionOptions& options) {
  const bool timed = !(options.ms_per_comparison > 0.0);
  TopologyMeasures fastest;
  for (int pass = 0; pass < (timed ? kTimingPasses : 1); ++pass) {
    const TopologyMeasures measures =
        evaluateTopology(demonstration, topology, tests, options.parameters, options.threshold);
    if (pass == 0 || measures.mean_ms < fastest.mean_ms)
      fastest = measures;
  }
  if (!timed)
    fastest.mean_ms = fastest.mean_work * options.ms_per_comparison;
  return fastest;
}

// The work budget a time budget converts to, by the slower time per comparison of the star and
// the complete tree, so that trees like either keep the budget; 0 (none) without a time budget.
double workBudget(const TopologySelectionResult& result, double max_duration_ms) {
  if (max_duration_ms <= 0.0)
    return 0.0;
  double ms_per_work = 0.0;
  for (const TopologyMeasures* measures : {&result.star_measures, &result.complete_measures}) {
    if (measures->mean_work > 0.0)
      ms_per_work = std::max(ms_per_work, measures->mean_ms / measures->mean_work);
  }
  return ms_per_work > 0.0 ? max_duration_ms / ms_per_work : 0.0;
}

TopologyCost costOf(const TopologySelectionResult& result,
                    const TopologySelectionOptions& options) {
  const std::size_t test_count = result.tests.valid.size() + result.tests.invalid.size();
  const double valid_share =
      test_count > 0 ? static_cast<double>(result.tests.valid.size()) / test_count : 0.5;
  return TopologyCost(result.star_measures, result.complete_measures, options.alpha, options.beta,
                      result.max_mean_work, valid_share);
}

// The test configurations, the star and complete topologies' measures (which normalise the cost
// and convert a time budget into work) and the work budget.
TopologySelectionResult prepareSelection(const asr_ism::Demonstration& demonstration,
                                         const TopologySelectionOptions& options,
                                         const TestConfigurations* given_tests) {
  TopologySelectionResult result;
  const RelationTopology complete = RelationTopology::complete(demonstration.objects());
  if (given_tests) {
    result.tests = *given_tests;
  } else {
    const IsmTree complete_tree = generateIsmTree(demonstration, complete, options.parameters);
    result.tests = generateTestConfigurations(demonstration, complete_tree, options.test_count,
                                              options.seed, options.threshold);
  }
  result.star = RelationTopology::star(demonstration.objects(), chooseStarCenter(demonstration));
  result.star_measures = fastestMeasures(demonstration, result.star, result.tests, options);
  result.complete_measures = fastestMeasures(demonstration, complete, result.tests, options);
  result.max_mean_work = workBudget(result, options.max_duration_ms);
  return result;
}

struct Starts {
  Candidate best;       // where the search begins
  Candidate best_star;  // the cheapest star
};

// The start: the given topology, or the best of all stars and the complete topology (which
// wins where its work is within the budget and the stars make many errors; the climb then
// removes the relations that the errors do not need).
Starts evaluateStarts(const TopologySelectionResult& result,
                      const TopologySelectionOptions& options, const TopologyCost& cost,
                      Evaluator& evaluator) {
  const std::vector<ObjectKey>& objects = result.star.objects();
  std::vector<RelationTopology> starts;
  if (options.start) {
    starts.push_back(*options.start);
  } else {
    for (std::size_t center = 0; center < objects.size(); ++center)
      starts.push_back(RelationTopology::star(objects, center));
    starts.push_back(RelationTopology::complete(objects));
  }
  Starts found;
  found.best_star = {result.star, cost(result.star_measures)};
  const auto results = evaluator.evaluate(starts);
  for (std::size_t i = 0; i < starts.size(); ++i) {
    if (!results[i])
      continue;
    const Candidate candidate = {starts[i], results[i]->cost};
    if (candidate.cost < found.best.cost - 1e-12)
      found.best = candidate;
    if (!options.start && i < objects.size() && candidate.cost < found.best_star.cost - 1e-12)
      found.best_star = candidate;
  }
  if (!std::isfinite(found.best.cost))  // the budget ended before any start: use the star
    found.best = found.best_star;
  return found;
}

// Restarts from the other ends of the search space: the best star grown by the relations that
// the invalid configurations break (near the few-false-positive topologies that climbing from a
// star rarely reaches), and the complete topology (a climb down from it keeps the relations the
// errors need). Either is the start instead (in `starts.best`) if it costs less than the best.
std::vector<RelationTopology> otherStarts(Starts& starts, const RelationViolations& violations,
                                          const TopologySelectionOptions& options,
                                          Evaluator& evaluator) {
  std::vector<RelationTopology> other_starts;
  if (options.start)
    return other_starts;
  Candidate& best = starts.best;
  const RelationTopology grown =
      withCatchingRelations(starts.best_star.topology, violations, options.max_tree_height);
  for (const RelationTopology& start :
       {grown, RelationTopology::complete(best.topology.objects())}) {
    const auto results = evaluator.evaluate({start});
    if (results[0] && results[0]->cost < best.cost - 1e-12) {
      other_starts.push_back(best.topology);
      best = {start, results[0]->cost};
    } else if (start != best.topology &&
               std::find(other_starts.begin(), other_starts.end(), start) == other_starts.end()) {
      other_starts.push_back(start);
    }
  }
  return other_starts;
}

// Annealing from `best`, or hill climbing with restarts: the other ends first, then starts near
// the best topology so far. `best` is updated along the way.
void search(Candidate& best, const std::vector<RelationTopology>& other_starts,
            const RelationViolations& violations, const TopologySelectionOptions& options,
            Evaluator& evaluator) {
  asr_ism::PortableRandom random(options.seed ^ 0x5eedu);
  const std::size_t batch_size = std::max<std::size_t>(1, options.batch_size);
  if (options.method == TopologySearchMethod::kSimulatedAnnealing) {
    anneal(best, evaluator, options, violations, batch_size, random, best);
    return;
  }
  climb(best, evaluator, options, violations, batch_size, random, best);
  for (std::size_t restart = 0; restart < options.restarts && evaluator.budgetLeft(); ++restart) {
    const RelationTopology start =
        restart < other_starts.size()
            ? other_starts[restart]
            : perturbed(best.topology, 2 + restart, options.max_tree_height, random);
    const auto results = evaluator.evaluate({start});
    if (!results[0])
      break;
    climb({start, results[0]->cost}, evaluator, options, violations, batch_size, random, best);
  }
}

// The cheapest topology evaluated, measured alone. The work budget was converted by the star's
// and complete tree's time per comparison, but trees of more, smaller ISMs take up to a quarter
// longer per comparison. If the chosen tree misses the time budget, the budget is converted
// again by its own time per comparison and the cheapest topology evaluated within that is
// chosen instead.
void chooseWithinTimeBudget(TopologySelectionResult& result,
                            const asr_ism::Demonstration& demonstration,
                            const TopologySelectionOptions& options, Evaluator& evaluator) {
  const Evaluated* chosen = evaluator.cheapest();
  result.measures = fastestMeasures(demonstration, chosen->topology, result.tests, options);
  for (int round = 0; round < kBudgetRechecks && options.max_duration_ms > 0.0 &&
                      result.measures.mean_ms > options.max_duration_ms;
       ++round) {
    result.max_mean_work =
        std::min(result.max_mean_work,
                 result.measures.mean_work * options.max_duration_ms / result.measures.mean_ms);
    evaluator.setCost(costOf(result, options));
    const Evaluated* within = evaluator.cheapest();
    if (within == chosen)
      break;  // nothing evaluated does better
    chosen = within;
    result.measures = fastestMeasures(demonstration, chosen->topology, result.tests, options);
  }
  result.topology = chosen->topology;
  result.cost = chosen->cost;
}

}  // namespace

TopologySelectionResult selectTopology(
    const asr_ism::Demonstration& demonstration, const TopologySelectionOptions& options,
    const std::function<void(const TopologySelectionProgress&)>& progress,
    const TestConfigurations* given_tests) {
  checkSelectionInput(demonstration, options);
  TopologySelectionResult result = prepareSelection(demonstration, options, given_tests);
  Evaluator evaluator(demonstration, result.tests, options, progress);
  evaluator.remember(result.star, result.star_measures);
  evaluator.remember(RelationTopology::complete(demonstration.objects()), result.complete_measures);
  if (options.max_duration_ms > 0.0)
    evaluator.setWorkBudget(result.max_mean_work);
  const TopologyCost cost = costOf(result, options);
  evaluator.setCost(cost);

  Starts starts = evaluateStarts(result, options, cost, evaluator);
  const RelationViolations violations(demonstration, result.tests.invalid, options.parameters,
                                      kBrokenRelationDeficit);
  const std::vector<RelationTopology> other_starts =
      otherStarts(starts, violations, options, evaluator);
  evaluator.report(starts.best.cost, starts.best.cost);
  search(starts.best, other_starts, violations, options, evaluator);

  chooseWithinTimeBudget(result, demonstration, options, evaluator);
  result.evaluated = evaluator.evaluated();
  return result;
}

}  // namespace asr_ism_tree
