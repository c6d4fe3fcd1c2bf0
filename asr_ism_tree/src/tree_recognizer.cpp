#include "asr_ism_tree/tree_recognizer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <tuple>

#include "asr_common/input_error.hpp"
#include "asr_ism_tree/estimate_matching.hpp"
#include "asr_ism_tree/repeated_detections.hpp"
#include "best_fitting_repeats.hpp"
#include "exact_best_search.hpp"
#include "object_subsets.hpp"
#include "pose_diverse_results.hpp"
#include "relaxed_tree_bound.hpp"

namespace asr_ism_tree {

using asr_ism::IsmInput;
using asr_ism::IsmResult;

// The results of one ISM and, per input, where that input came from: the index of the estimate
// in the configuration for a real object, the index of the child ISM's result for a placeholder.
struct EvaluatedIsm {
  std::vector<IsmResult> results;
  std::vector<int> input_origin;
};

// Root objectives within this of each other are equal (rounding of sums of similarities).
constexpr double kObjectiveMargin = 1e-9;
constexpr double kUnbounded = std::numeric_limits<double>::infinity();
// A vote cast, binned and gathered costs about as much as 50 comparisons (2 us against 20-50 ns
// on the development machine), in the work the recognitions of object subsets may do.
constexpr std::size_t kWorkPerVote = 50;

// Votes and results grouped within 1 % of the support radius and of the maximum angle
// deviation: on the synthetic scenes of exact_search_test, coarser groups gave looser bounds.
RelaxedBoundParameters relaxedBoundParameters(const IsmTree& tree, std::size_t max_work) {
  return {0.01 * tree.parameters.supportRadius(), 0.01 * tree.parameters.max_angle_deviation,
          max_work};
}

// Pose-diverse results passed up lie 10 % of the support radius or of the maximum angle
// deviation apart: on the recordings' and the synthetic property cases, 30 % or more suppressed
// the hypotheses the parents needed, and none (votes at distinct poses only) let near-duplicates
// fill the places (docs/recognition.md).
constexpr double kDiverseFraction = 0.1;

// Evaluations over the repeats that fit the best instance best, each from the previous one's
// best, while the best rises: with the best-fitting repeat of each object (where the set a
// detector saw best is among the repeats, this reaches it at the cost of one evaluation over
// the representatives), then, below the bound, the three best-fitting (on the clutter series
// without its recorded set, complete tree, 100 / 250 / 1,000 estimates, the best rose from
// 0.946 / 0.967 / 0.969 with one to 0.971 / 0.975 / 0.992; five added < 0.002); then the same
// two with the repeats nearest to each expected pose of an object as well (a complete tree's
// best may match a different repeat in each ISM: up to 0.010 more, docs/recognition.md).
constexpr int kFittingRounds = 3;
constexpr std::size_t kFittedPerObject = 3;

// Thrown where the exact search would exceed its budget.
struct ExactSearchTooLarge {};

// What the exact search may still spend in one recognition, over all its labellings.
struct ExactSearchBudget {
  std::size_t max_votes;         // per evaluation of one ISM
  std::size_t comparisons_left;  // vote-to-hypothesis comparisons
  std::size_t votes_left;        // cast over all evaluations
  std::size_t pose_steps_left;   // compositions seeking the poses of the pose gap
  std::size_t comparisons_used = 0;
  std::size_t votes_used = 0;
  std::size_t pose_steps_used = 0;
  bool pose_gap_open = false;  // the steps ran out: no more are sought
};

// A pose-only input's weight: below every result's objective (at least its chain's estimate's,
// 1), so no hypothesis that matters matches it; it only adds its votes as hypotheses.
constexpr double kPoseOnlyWeight = 0.5;

// The first evaluation (a few results per sub-ISM) and, where its best instance may not be the
// exhaustive search's, the exact search's, whose root holds the results reaching the first best;
// where repeated detections were merged, an evaluation over the repeats that fit the best
// instance best, where its best is higher, and the exact search over every estimate, whose root
// holds the results reaching the best of those.
struct TreeEvaluation {
  std::vector<EvaluatedIsm> first;
  std::vector<EvaluatedIsm> exact;
  bool has_exact = false;
  std::vector<EvaluatedIsm> fitted;
  bool has_fitted = false;
  std::vector<EvaluatedIsm> over_repeats;
  bool has_over_repeats = false;
};

namespace {

// One leaf of the tree as it takes part in an assembled instance.
struct LeafOutcome {
  int object = -1;
  int estimate = -1;  // -1 if unmatched
  double contribution = 0.0;
  double position_compliance = 0.0;
  double orientation_compliance = 0.0;
  Pose expected;  // if matched: from where its vote would fall on the ISM's reference pose
};

class InstanceAssembler {
 public:
  InstanceAssembler(const IsmTree& tree, const std::vector<EvaluatedIsm>& evaluated)
      : tree_(tree), evaluated_(evaluated) {}

  // Follows the links from placeholder matches down to the child results (Algo. 3 and 4).
  void collect(int ism, int result_index, double factor, std::vector<LeafOutcome>& leaves,
               std::vector<InstanceIsm>& isms) const {
    const IsmResult* result = result_index >= 0 ? &evaluated_[ism].results[result_index] : nullptr;
    if (result != nullptr) {
      isms[ism].objective = result->objective;
      isms[ism].reference_pose = result->reference_pose;
      isms[ism].recognized = true;
    }
    const auto& members = tree_.isms[ism].members;
    for (std::size_t m = 0; m < members.size(); ++m) {
      const asr_ism::MemberMatch* match =
          result != nullptr && result->matches[m].matched() ? &result->matches[m] : nullptr;
      const int origin = match ? evaluated_[ism].input_origin[match->input] : -1;
      const double contribution = match ? factor * match->similarity() : 0.0;
      if (members[m].isPlaceholder()) {
        collect(members[m].child_ism, origin, contribution, leaves, isms);
        continue;
      }
      LeafOutcome leaf;
      leaf.object = tree_.topology.indexOf(members[m].object);
      if (match) {
        leaf.estimate = origin;
        leaf.contribution = contribution;
        leaf.position_compliance = match->position_compliance;
        leaf.orientation_compliance = match->orientation_compliance;
        leaf.expected = asr_common::compose(
            result->reference_pose,
            asr_common::inverse(
                members[m].relative_poses[match->relative_pose].reference_in_member));
      }
      leaves.push_back(leaf);
    }
  }

 private:
  const IsmTree& tree_;
  const std::vector<EvaluatedIsm>& evaluated_;
};

}  // namespace

TreeRecognizer::TreeRecognizer(const IsmTree& tree, TreeRecognitionParameters parameters,
                               asr_ism::ThreadPool* pool)
    : tree_(tree), parameters_(parameters), pool_(pool) {
  tree_.validate("ISM tree");
  if (parameters_.results_passed_up == 0) {
    throw asr_common::InputError("tree recognition: results_passed_up must be at least 1");
  }
  if (parameters_.max_estimates == 0 || parameters_.max_labellings == 0) {
    throw asr_common::InputError("tree recognition: max_estimates and max_labellings must be >= 1");
  }
  levels_.resize(tree_.height());
  for (std::size_t ism = 0; ism < tree_.isms.size(); ++ism) {
    levels_[levels_.size() - 1 - tree_.level[ism]].push_back(static_cast<int>(ism));
  }
  for (const std::vector<int>& level : levels_)
    bottom_up_.insert(bottom_up_.end(), level.begin(), level.end());
  for (std::size_t ism = 0; ism < tree_.isms.size(); ++ism) {
    const auto& members = tree_.isms[ism].members;
    for (std::size_t m = 0; m < members.size(); ++m) {
      if (!members[m].isPlaceholder()) {
        leaves_.push_back({static_cast<int>(ism), static_cast<int>(m),
                           tree_.topology.indexOf(members[m].object)});
      }
    }
  }
}

namespace {

// The estimates in a canonical order, so that neither the input order nor where the world frame
// lies can matter: by key, then by distance from the centroid of the estimates the scene can
// match at 1e-9 m (a rigid motion changes it by rounding only; clutter does not move it, so the
// answer does not depend on clutter), then by pose (for poses that far from a tie only).
std::vector<int> canonicalOrder(const asr_common::Configuration& configuration,
                                const std::vector<Pose>& poses, const EstimateMatching& matching) {
  std::vector<int> canonical(configuration.size());
  std::iota(canonical.begin(), canonical.end(), 0);
  const auto sort_key = [&](int i) {
    const Pose& p = poses[i];
    return std::make_tuple(std::cref(configuration[i].key), p.position.x(), p.position.y(),
                           p.position.z(), p.orientation.w(), p.orientation.x(), p.orientation.y(),
                           p.orientation.z(), i);
  };
  std::sort(canonical.begin(), canonical.end(),
            [&](int a, int b) { return sort_key(a) < sort_key(b); });
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  std::size_t matchable = 0;
  for (int i : canonical) {  // summed in an order the input order cannot change
    if (matching.candidates[i].empty())
      continue;
    centroid += poses[i].position;
    ++matchable;
  }
  centroid /= std::max<double>(1.0, static_cast<double>(matchable));
  std::vector<std::int64_t> distance_level(canonical.size());
  for (std::size_t i = 0; i < poses.size(); ++i)
    distance_level[i] = std::llround((poses[i].position - centroid).norm() / 1e-9);
  std::stable_sort(canonical.begin(), canonical.end(), [&](int a, int b) {
    return std::tie(configuration[a].key, distance_level[a]) <
           std::tie(configuration[b].key, distance_level[b]);
  });
  return canonical;
}

// The mean over the scene's objects of their similarity; missing objects count 0.
double objectConfidence(const SceneInstance& instance, std::size_t object_count) {
  double sum = 0.0;
  for (const InstanceObject& object : instance.objects)
    sum += object.similarity;
  return object_count == 0 ? 0.0 : std::min(1.0, sum / static_cast<double>(object_count));
}

// Two instances from different labellings of id-less estimates that match every object to the
// same estimate equally well are one instance.
bool sameInstance(const SceneInstance& a, const SceneInstance& b) {
  if (std::abs(a.confidence - b.confidence) > 1e-12 || a.objects.size() != b.objects.size())
    return false;
  for (std::size_t o = 0; o < a.objects.size(); ++o) {
    if (a.objects[o].key != b.objects[o].key || a.objects[o].estimate != b.objects[o].estimate ||
        std::abs(a.objects[o].similarity - b.objects[o].similarity) > 1e-12)
      return false;
  }
  return true;
}

void addIsmWork(asr_ism::IsmRecognitionStats& total, const asr_ism::IsmRecognitionStats& part) {
  total.votes += part.votes;
  total.bins += part.bins;
  total.candidates += part.candidates;
  total.comparisons += part.comparisons;
  total.neighbourhood_votes += part.neighbourhood_votes;
}

// The best objective of the root's results, 0 if none.
double bestOf(const std::vector<EvaluatedIsm>& evaluated) {
  return evaluated[0].results.empty() ? 0.0 : evaluated[0].results.front().objective;
}

// The best objective any of the evaluation's roots reached, 0 if none.
double bestRootObjective(const TreeEvaluation& evaluation) {
  double best = 0.0;
  for (const auto& [evaluated, ran] :
       {std::make_pair(&evaluation.first, true),
        std::make_pair(&evaluation.exact, evaluation.has_exact),
        std::make_pair(&evaluation.fitted, evaluation.has_fitted),
        std::make_pair(&evaluation.over_repeats, evaluation.has_over_repeats)}) {
    if (ran && !(*evaluated)[0].results.empty())
      best = std::max(best, (*evaluated)[0].results.front().objective);
  }
  return best;
}

// Per object its estimates if it is in `subset`, none otherwise.
std::vector<std::vector<int>> estimatesWithin(ObjectSet subset,
                                              std::vector<std::vector<int>> estimates_of_object) {
  for (std::size_t object = 0; object < estimates_of_object.size(); ++object) {
    if (((subset >> object) & 1U) == 0U)
      estimates_of_object[object].clear();
  }
  return estimates_of_object;
}

using RootResults = std::vector<std::pair<const std::vector<EvaluatedIsm>*, std::size_t>>;

// The root results that become instances: the first evaluation's, and the best of the exact
// searches' where it is better, in place of the first results it makes redundant (their
// estimates are all among its own).
RootResults rootResultsToAssemble(const TreeEvaluation& evaluation) {
  RootResults chosen;
  const auto& first = evaluation.first[0].results;
  const std::vector<EvaluatedIsm>* better = nullptr;
  double best = first.empty() ? -std::numeric_limits<double>::infinity() : first.front().objective;
  for (const auto& [searched, ran] :
       {std::make_pair(&evaluation.exact, evaluation.has_exact),
        std::make_pair(&evaluation.fitted, evaluation.has_fitted),
        std::make_pair(&evaluation.over_repeats, evaluation.has_over_repeats)}) {
    const auto& results = (*searched)[0].results;
    if (ran && !results.empty() && results.front().objective > best + 1e-9) {
      better = searched;
      best = results.front().objective;
    }
  }
  const IsmResult* exact_best = better != nullptr ? &(*better)[0].results.front() : nullptr;
  if (better != nullptr)
    chosen.emplace_back(better, 0);
  for (std::size_t r = 0; r < first.size(); ++r) {
    const bool redundant = exact_best != nullptr &&
                           std::includes(exact_best->estimates.begin(), exact_best->estimates.end(),
                                         first[r].estimates.begin(), first[r].estimates.end());
    if (!redundant)
      chosen.emplace_back(&evaluation.first, r);
  }
  return chosen;
}

// Puts the best root result of a recognition over fewer objects first, in place of the results
// it makes redundant (their estimates are all among its own).
void preferBestOf(const TreeEvaluation& subset_evaluation, RootResults& chosen) {
  const auto best = rootResultsToAssemble(subset_evaluation).front();
  const std::vector<int>& used = (*best.first)[0].results[best.second].estimates;
  const auto redundant = [&](const auto& root_result) {
    const std::vector<int>& estimates =
        (*root_result.first)[0].results[root_result.second].estimates;
    return std::includes(used.begin(), used.end(), estimates.begin(), estimates.end());
  };
  chosen.erase(std::remove_if(chosen.begin(), chosen.end(), redundant), chosen.end());
  chosen.insert(chosen.begin(), best);
}

}  // namespace

void TreeRecognizer::evaluateIsm(int ism, double from, std::vector<EvaluatedIsm>& evaluated,
                                 const std::vector<Pose>& poses,
                                 const std::vector<std::vector<int>>& estimates_of_object,
                                 asr_ism::IsmRecognitionStats& stats, ExactSearchBudget* budget,
                                 std::size_t diverse,
                                 const std::vector<double>* member_from) const {
  const auto& members = tree_.isms[ism].members;
  std::vector<IsmInput> inputs;
  EvaluatedIsm& current = evaluated[ism];
  current.input_origin.clear();
  for (std::size_t m = 0; m < members.size(); ++m) {
    if (members[m].isPlaceholder()) {
      const auto& child_results = evaluated[members[m].child_ism].results;
      for (std::size_t r = 0; r < child_results.size(); ++r) {
        inputs.push_back({static_cast<int>(m), child_results[r].reference_pose,
                          child_results[r].objective, child_results[r].estimates});
        current.input_origin.push_back(static_cast<int>(r));
      }
      continue;
    }
    for (int estimate : estimates_of_object[tree_.topology.indexOf(members[m].object)]) {
      inputs.push_back({static_cast<int>(m), poses[estimate], 1.0, {estimate}});
      current.input_origin.push_back(estimate);
    }
  }
  if (budget != nullptr && member_from != nullptr && !budget->pose_gap_open) {
    std::vector<PoseOnlyInput> pose_only;
    const std::size_t steps_before = budget->pose_steps_left;
    if (!poseGapCandidates(tree_, ism, from, inputs, *member_from, poses, estimates_of_object,
                           budget->pose_steps_left, pose_only))
      budget->pose_gap_open = true;
    budget->pose_steps_used += steps_before - budget->pose_steps_left;
    for (const PoseOnlyInput& candidate : pose_only) {
      inputs.push_back({candidate.member, candidate.pose, kPoseOnlyWeight, {candidate.estimate}});
      current.input_origin.push_back(-1);  // no result of the child's to follow
    }
  }
  asr_ism::IsmResultSelection selection;
  if (ism != 0) {
    selection.best_count = parameters_.results_passed_up;
    selection.every_result_from = parameters_.pass_every_result ? 0.0 : from;
  } else if (std::isfinite(from)) {
    // A root asked for results beyond a best found before serves callers that use only its best
    // (the exact searches, the fitted and the diverse evaluations): with one result the bar rises
    // to the best found so far, not only to `from`.
    selection.at_least = from;
    selection.best_count = 1;
  }
  if (budget == nullptr) {
    current.results =
        asr_ism::recognizeIsm(tree_.isms[ism], inputs, tree_.parameters, selection, &stats);
    return;
  }
  std::size_t votes = 0;
  for (const IsmInput& input : inputs)
    votes += members[input.member].relative_poses.size();
  if (votes > budget->max_votes || votes > budget->votes_left)
    throw ExactSearchTooLarge{};
  budget->votes_left -= votes;
  budget->votes_used += votes;
  selection.max_comparisons = budget->comparisons_left;
  asr_ism::IsmRecognitionStats spent;
  try {
    current.results =
        asr_ism::recognizeIsm(tree_.isms[ism], inputs, tree_.parameters, selection, &spent);
  } catch (const asr_ism::IsmWorkLimitExceeded&) {
    budget->comparisons_used += budget->comparisons_left;
    budget->comparisons_left = 0;
    throw ExactSearchTooLarge{};
  }
  if (diverse > 0 && ism != 0) {
    current.results = poseDiverseResults(std::move(current.results), diverse,
                                         kDiverseFraction * tree_.parameters.supportRadius(),
                                         kDiverseFraction * tree_.parameters.max_angle_deviation);
  }
  budget->comparisons_left -= spent.comparisons;
  budget->comparisons_used += spent.comparisons;
  stats.votes += spent.votes;
  stats.bins += spent.bins;
  stats.candidates += spent.candidates;
  stats.comparisons += spent.comparisons;
  stats.neighbourhood_votes += spent.neighbourhood_votes;
}

bool TreeRecognizer::searchExactly(std::vector<EvaluatedIsm>& evaluated, bool from_lower_bounds,
                                   double known_best, const std::vector<Pose>& poses,
                                   const std::vector<std::vector<int>>& estimates_of_object,
                                   std::vector<asr_ism::IsmRecognitionStats>& ism_stats,
                                   ExactSearchBudget& budget, TreeRecognitionStats* stats,
                                   std::size_t TreeRecognitionStats::*given_up) const {
  std::vector<bool> object_seen(tree_.objects().size());
  for (std::size_t object = 0; object < object_seen.size(); ++object)
    object_seen[object] = !estimates_of_object[object].empty();
  const auto evaluate = [&](int ism, double from, const std::vector<double>& member_from) {
    evaluateIsm(ism, from, evaluated, poses, estimates_of_object, ism_stats[ism], &budget, 0,
                &member_from);
  };
  const auto best = [&](int ism) {
    const auto& results = evaluated[ism].results;
    return results.empty() ? 0.0 : results.front().objective;
  };
  const double best_before = best(0);
  const auto start = from_lower_bounds ? ExactBestSearch::Start::kLowerBounds
                                       : ExactBestSearch::Start::kFirstEvaluation;
  // Seeking the poses of the pose gap costs most where the search gives up anyway: it runs
  // without them first and, only where that completes, once more with them.
  const std::vector<EvaluatedIsm> starting_results = evaluated;
  const bool seek_poses = !budget.pose_gap_open;
  budget.pose_gap_open = true;
  try {
    if (!ExactBestSearch(tree_, object_seen, evaluate, best, start, known_best).run(bottom_up_)) {
      budget.pose_gap_open = !seek_poses;
      return false;
    }
    budget.pose_gap_open = !seek_poses;
    if (seek_poses) {
      std::vector<EvaluatedIsm> without_poses = std::move(evaluated);
      evaluated = starting_results;
      try {
        ExactBestSearch(tree_, object_seen, evaluate, best, start, known_best).run(bottom_up_);
      } catch (const ExactSearchTooLarge&) {
        budget.pose_gap_open = true;
        evaluated = std::move(without_poses);
      }
    }
    if (stats != nullptr && budget.pose_gap_open)
      stats->pose_gaps_left_open += 1;
    return true;
  } catch (const ExactSearchTooLarge&) {
    budget.pose_gap_open = !seek_poses;
  }
  // Over the same estimates, a second evaluation may find a better instance than the first.
  const bool better =
      !from_lower_bounds && evaluateDiversely(evaluated, std::max(best_before, known_best), poses,
                                              estimates_of_object, ism_stats, stats);
  // The best found before stands; the relaxed bound, if asked for, may show that nothing beats
  // it, or by how much something could.
  std::optional<double> bound;
  if (parameters_.relaxed_bound_max_work > 0) {
    std::size_t work = 0;
    bound =
        relaxedRootBound(tree_, bottom_up_, poses, estimates_of_object,
                         relaxedBoundParameters(tree_, parameters_.relaxed_bound_max_work), &work);
    if (stats != nullptr)
      stats->relaxed_bound_work += work;
  }
  const double found = better ? best(0) : std::max(best_before, known_best);
  const double gap = bound ? std::max(0.0, *bound - found) : kUnbounded;
  if (stats != nullptr) {
    if (gap <= kObjectiveMargin) {
      ++stats->exact_searches_proven_by_bound;
    } else {
      ++(stats->*given_up);
      stats->largest_possible_shortfall =
          std::max(stats->largest_possible_shortfall, gap / static_cast<double>(leaves_.size()));
    }
  }
  return better;
}

bool TreeRecognizer::evaluateDiversely(std::vector<EvaluatedIsm>& evaluated, double first_best,
                                       const std::vector<Pose>& poses,
                                       const std::vector<std::vector<int>>& estimates_of_object,
                                       std::vector<asr_ism::IsmRecognitionStats>& ism_stats,
                                       TreeRecognitionStats* stats) const {
  const std::size_t diverse = parameters_.diverse_results_passed_up;
  if (diverse == 0)
    return false;
  ExactSearchBudget budget{parameters_.exact_search_max_votes, parameters_.diverse_max_comparisons,
                           parameters_.exact_search_max_total_votes, 0};
  bool completed = true;
  try {
    // Sub-ISMs: every result (one per pose) before the suppression; the root: better ones only.
    for (int ism : bottom_up_) {
      evaluateIsm(ism, ism == 0 ? first_best + kObjectiveMargin : 0.0, evaluated, poses,
                  estimates_of_object, ism_stats[ism], &budget, diverse);
    }
  } catch (const ExactSearchTooLarge&) {
    completed = false;
  }
  const bool better = completed && !evaluated[0].results.empty() &&
                      evaluated[0].results.front().objective > first_best + kObjectiveMargin;
  if (stats != nullptr) {
    ++stats->diverse_evaluations;
    stats->diverse_evaluations_better += better ? 1 : 0;
    stats->diverse_evaluations_given_up += completed ? 0 : 1;
    stats->diverse_comparisons += budget.comparisons_used;
  }
  return better;
}

void TreeRecognizer::evaluateFirst(const std::vector<Pose>& poses,
                                   const std::vector<std::vector<int>>& estimates_of_object,
                                   std::vector<EvaluatedIsm>& evaluated,
                                   std::vector<asr_ism::IsmRecognitionStats>& ism_stats,
                                   double root_at_least) const {
  // Bottom-up evaluation (Algo. 2), level by level; the ISMs of one level are independent.
  evaluated.resize(tree_.isms.size());
  const auto evaluate = [&](int ism, double from) {
    evaluateIsm(ism, ism == 0 ? root_at_least : from, evaluated, poses, estimates_of_object,
                ism_stats[ism]);
  };
  constexpr double kOnlyTheBest = std::numeric_limits<double>::infinity();
  for (const std::vector<int>& level : levels_) {
    if (pool_ != nullptr && level.size() > 1) {
      pool_->parallelFor(level.size(), [&](std::size_t i) { evaluate(level[i], kOnlyTheBest); });
    } else {
      for (int ism : level)
        evaluate(ism, kOnlyTheBest);
    }
  }
}

double TreeRecognizer::seenLeaves(const std::vector<std::vector<int>>& estimates_of_object) const {
  return static_cast<double>(std::count_if(leaves_.begin(), leaves_.end(), [&](const Leaf& leaf) {
    return !estimates_of_object[leaf.object].empty();
  }));
}

bool TreeRecognizer::evaluateBestFittingRepeats(
    const std::vector<EvaluatedIsm>& first, const std::vector<Pose>& poses,
    const std::vector<std::vector<int>>& representatives,
    const std::vector<std::vector<int>>& every_estimate,
    std::vector<asr_ism::IsmRecognitionStats>& ism_stats, std::vector<EvaluatedIsm>& fitted) const {
  const RepeatedDetectionTolerance tolerance{tree_.parameters.supportRadius(),
                                             tree_.parameters.max_angle_deviation};
  const double bound = seenLeaves(every_estimate);
  std::vector<std::vector<int>> estimates = representatives;
  std::vector<EvaluatedIsm> candidate;
  bool better = false;
  const std::pair<std::size_t, bool> stages[] = {
      {1, false}, {kFittedPerObject, false}, {1, true}, {kFittedPerObject, true}};
  for (const auto& [per_object, nearest_to_each] : stages) {
    for (int round = 0; round < kFittingRounds; ++round) {
      const std::vector<EvaluatedIsm>& current = better ? fitted : first;
      if (current[0].results.empty() || bestOf(current) >= bound - kObjectiveMargin)
        return better;
      std::vector<LeafOutcome> leaves;
      std::vector<InstanceIsm> isms(tree_.isms.size());
      InstanceAssembler(tree_, current).collect(0, 0, 1.0, leaves, isms);
      std::vector<ExpectedPose> expected;
      for (const LeafOutcome& leaf : leaves) {
        if (leaf.estimate >= 0)
          expected.push_back({leaf.object, leaf.expected});
      }
      auto next = bestFittingRepeats(expected, representatives, every_estimate, poses, tolerance,
                                     per_object, nearest_to_each);
      if (next == estimates)
        break;
      // Only a better best counts: the root skips every hypothesis below it (where its
      // hypotheses match no input exactly, as in jittered clutter, scoring every one cost the
      // complete tree most of this evaluation).
      evaluateFirst(poses, next, candidate, ism_stats, bestOf(current) + kObjectiveMargin);
      if (bestOf(candidate) <= bestOf(current) + kObjectiveMargin)
        break;
      fitted = std::move(candidate);
      estimates = std::move(next);
      better = true;
    }
  }
  return better;
}

TreeEvaluation TreeRecognizer::evaluateIsms(
    const std::vector<Pose>& poses, const std::vector<std::vector<int>>& estimates_of_object,
    const std::vector<std::vector<int>>* with_repeats, TreeRecognitionStats* stats,
    ExactSearchBudget& budget, double known_best) const {
  TreeEvaluation evaluation;
  std::vector<EvaluatedIsm>& evaluated = evaluation.first;
  std::vector<asr_ism::IsmRecognitionStats> ism_stats(tree_.isms.size());
  evaluateFirst(poses, estimates_of_object, evaluated, ism_stats);
  const bool exact = parameters_.exact_best && !parameters_.pass_every_result;
  const bool over_repeats = exact && parameters_.exact_over_repeats && with_repeats != nullptr;
  if (over_repeats) {
    evaluation.has_fitted = evaluateBestFittingRepeats(evaluated, poses, estimates_of_object,
                                                       *with_repeats, ism_stats, evaluation.fitted);
  }
  // Where the repeats that fit best reach the bound (every seen leaf matched fully), that is the
  // exhaustive search's best, and nothing need be searched.
  const bool fitted_reach_bound =
      evaluation.has_fitted &&
      bestOf(evaluation.fitted) >= seenLeaves(*with_repeats) - kObjectiveMargin;
  if (stats != nullptr) {
    stats->fitted_repeats_better += evaluation.has_fitted ? 1 : 0;
    stats->fitted_repeats_at_bound += fitted_reach_bound ? 1 : 0;
  }
  if (exact && tree_.isms.size() > 1 && !fitted_reach_bound) {
    // Over the representatives only an instance better than the repeats that fit best matters:
    // the search asks for nothing below them (in the clutter series without its recorded set
    // the complete tree's search ran out of comparisons at its root; with that bar the bound
    // alone shows that no representatives beat the fitted repeats).
    const double fitted_best = evaluation.has_fitted ? bestOf(evaluation.fitted) : 0.0;
    evaluation.exact = evaluated;
    evaluation.has_exact = searchExactly(evaluation.exact, false, std::max(known_best, fitted_best),
                                         poses, estimates_of_object, ism_stats, budget, stats,
                                         &TreeRecognitionStats::exact_searches_given_up);
  }
  if (over_repeats && !fitted_reach_bound) {
    // Every result found over the representatives (or the repeats that fit best) is one over
    // every estimate too: their best is a lower bound the search over every repeat starts from
    // (docs/recognition.md).
    evaluation.over_repeats = evaluation.has_exact ? evaluation.exact : evaluated;
    if (evaluation.has_fitted && bestOf(evaluation.fitted) > bestOf(evaluation.over_repeats))
      evaluation.over_repeats = evaluation.fitted;
    evaluation.has_over_repeats =
        searchExactly(evaluation.over_repeats, true, known_best, poses, *with_repeats, ism_stats,
                      budget, stats, &TreeRecognitionStats::repeat_searches_given_up);
  }
  if (stats != nullptr) {
    for (const auto& s : ism_stats)
      addIsmWork(stats->isms, s);
    stats->root_results += evaluated[0].results.size();
  }
  return evaluation;
}

SceneInstance TreeRecognizer::assembleInstance(
    const std::vector<EvaluatedIsm>& evaluated, std::size_t root_result,
    const std::vector<Pose>& poses,
    const std::vector<std::vector<int>>& estimates_of_object) const {
  // Top-down assembly (Algo. 3 and 4) of one root result.
  std::vector<LeafOutcome> leaves;
  SceneInstance instance;
  instance.scene = tree_.scene;
  instance.isms.resize(tree_.isms.size());
  for (std::size_t ism = 0; ism < tree_.isms.size(); ++ism)
    instance.isms[ism].name = tree_.isms[ism].name;
  InstanceAssembler(tree_, evaluated)
      .collect(0, static_cast<int>(root_result), 1.0, leaves, instance.isms);
  const IsmResult& root = evaluated[0].results[root_result];
  instance.pose = root.reference_pose;
  instance.confidence = std::min(1.0, root.objective / static_cast<double>(leaves_.size()));
  for (std::size_t object = 0; object < tree_.objects().size(); ++object) {
    InstanceObject entry;
    entry.key = tree_.objects()[object];
    double best_contribution = -1.0;
    int matched = 0;
    for (const LeafOutcome& leaf : leaves) {
      if (leaf.object != static_cast<int>(object))
        continue;
      ++entry.appearances;
      entry.similarity += leaf.contribution;
      if (leaf.estimate < 0)
        continue;
      ++matched;
      entry.position_compliance += leaf.position_compliance;
      entry.orientation_compliance += leaf.orientation_compliance;
      if (leaf.contribution > best_contribution) {
        best_contribution = leaf.contribution;
        entry.estimate = leaf.estimate;
      }
    }
    if (entry.estimate < 0) {
      if (estimates_of_object[object].empty()) {
        instance.missing.push_back(entry.key);
        continue;
      }
      entry.estimate = estimates_of_object[object].front();
    }
    entry.pose = poses[entry.estimate];
    entry.similarity /= std::max(1, entry.appearances);
    if (matched > 0) {
      entry.position_compliance /= matched;
      entry.orientation_compliance /= matched;
    }
    instance.objects.push_back(entry);
  }
  instance.object_confidence = objectConfidence(instance, tree_.objects().size());
  return instance;
}

bool TreeRecognizer::searchObjectSubsets(const std::vector<Pose>& poses,
                                         const std::vector<std::vector<int>>& estimates_of_object,
                                         const std::vector<std::vector<int>>& every_estimate,
                                         const TreeEvaluation& evaluation,
                                         TreeRecognitionStats& stats,
                                         TreeEvaluation& better) const {
  if (parameters_.object_subsets_max_work == 0 || tree_.objects().size() > 64)
    return false;
  // An ISM over objects only tried every hypothesis in the first evaluation: its best there is
  // its maximum, unless that ran over the representatives of repeated detections only.
  const bool over_every_estimate = estimates_of_object == every_estimate;
  std::vector<double> maximum(tree_.isms.size(), kUnbounded);
  for (std::size_t ism = 0; ism < tree_.isms.size(); ++ism) {
    const auto& members = tree_.isms[ism].members;
    const auto& results = evaluation.first[ism].results;
    const bool objects_only = std::none_of(members.begin(), members.end(),
                                           [](const auto& m) { return m.isPlaceholder(); });
    if (objects_only && over_every_estimate)
      maximum[ism] = results.empty() ? 0.0 : results.front().objective;
  }
  ObjectSet seen = 0;
  for (std::size_t object = 0; object < every_estimate.size(); ++object)
    seen |= every_estimate[object].empty() ? 0U : ObjectSet{1} << object;
  ObjectSubsetSearch search(SubsetBound(tree_, std::move(maximum)), seen,
                            bestRootObjective(evaluation), false);
  bool found = false;
  std::size_t work = 0;
  while (const std::optional<ObjectSet> subset = search.next()) {
    if (work >= parameters_.object_subsets_max_work) {
      ++stats.object_subset_searches_cut;
      break;
    }
    ++stats.object_subset_searches;
    // Recognised as if only these objects had been seen: with budgets of its own, so that its
    // best is that of the configuration without the other objects.
    const auto representatives = estimatesWithin(*subset, estimates_of_object);
    const auto all = estimatesWithin(*subset, every_estimate);
    TreeRecognitionStats spent;
    ExactSearchBudget budget{
        parameters_.exact_search_max_votes, parameters_.exact_search_max_comparisons,
        parameters_.exact_search_max_total_votes, parameters_.exact_search_max_pose_steps};
    // Only a better best matters: where the searches complete without one, the subset's
    // exhaustive best is no better than the best found, nor is any subset within it.
    TreeEvaluation evaluation =
        evaluateIsms(poses, representatives, representatives != all ? &all : nullptr, &spent,
                     budget, search.best());
    addIsmWork(stats.isms, spent.isms);
    work += spent.isms.comparisons + budget.pose_steps_used + kWorkPerVote * spent.isms.votes;
    const double reached = bestRootObjective(evaluation);
    if (reached > search.best() + kObjectiveMargin) {
      better = std::move(evaluation);
      found = true;
      ++stats.object_subsets_better;
    }
    search.report(*subset, reached,
                  spent.exact_searches_given_up + spent.repeat_searches_given_up +
                          spent.pose_gaps_left_open ==
                      0);
  }
  stats.object_subset_work += work;
  return found;
}

std::size_t TreeRecognizer::mergeRepeated(std::vector<std::vector<int>>& estimates_of_object,
                                          const std::vector<Pose>& poses) const {
  const RepeatedDetectionTolerance tolerance{tree_.parameters.supportRadius(),
                                             tree_.parameters.max_angle_deviation};
  std::size_t left_out = 0;
  for (std::vector<int>& estimates : estimates_of_object) {
    const std::size_t before = estimates.size();
    estimates = mergeRepeatedDetections(estimates, poses, tolerance);
    left_out += before - estimates.size();
  }
  return left_out;
}

bool TreeRecognizer::searchesReachTheExhaustiveBest(bool merged) const {
  // Without merged repeats, every estimate entered; with them, only the search over every repeat
  // (or fitted repeats at the bound) reaches past the representatives.
  if (merged &&
      !(parameters_.exact_best && parameters_.exact_over_repeats && !parameters_.pass_every_result))
    return false;
  // A single ISM's first evaluation tries every hypothesis over every input; a tree's sub-ISMs
  // pass up their few best results only, unless the exact search (or every result) follows.
  return parameters_.exact_best || parameters_.pass_every_result || tree_.isms.size() == 1;
}

std::vector<SceneInstance> TreeRecognizer::recognize(const asr_common::Configuration& configuration,
                                                     TreeRecognitionStats* stats) const {
  if (configuration.size() > parameters_.max_estimates) {
    throw asr_common::InputError("scene '" + tree_.scene +
                                 "': " + std::to_string(configuration.size()) +
                                 " object estimates, more than the configured maximum of " +
                                 std::to_string(parameters_.max_estimates) + " per recognition");
  }
  const std::vector<Pose> poses = asr_common::validatedPoses(configuration);
  const EstimateMatching matching = matchEstimates(tree_.objects(), configuration);
  const std::vector<int> canonical = canonicalOrder(configuration, poses, matching);
  const std::size_t labellings = matching.labellingCount();
  if (labellings > parameters_.max_labellings) {
    throw asr_common::InputError(
        "scene '" + tree_.scene + "': the estimates without a known id could stand for the " +
        "objects of their types in more than " + std::to_string(parameters_.max_labellings) +
        " ways; give their ids, or fewer estimates of types the scene has several objects of");
  }
  TreeRecognitionStats unasked;
  TreeRecognitionStats& counted = stats != nullptr ? *stats : unasked;
  counted = TreeRecognitionStats{};
  std::vector<SceneInstance> instances;
  bool complete = true;
  ExactSearchBudget budget{
      parameters_.exact_search_max_votes, parameters_.exact_search_max_comparisons,
      parameters_.exact_search_max_total_votes, parameters_.exact_search_max_pose_steps};
  for (std::size_t labelling = 0; labelling < labellings; ++labelling) {
    const auto every_estimate =
        matching.estimatesOfObjects(labelling, tree_.objects().size(), canonical);
    auto estimates_of_object = every_estimate;
    const std::size_t merged =
        parameters_.merge_repeated_detections ? mergeRepeated(estimates_of_object, poses) : 0;
    counted.merged_estimates += merged;
    // A search that gave up, or completed with the pose gap open, may fall short of the
    // exhaustive best, and so possibly of the best with an object left out.
    const auto falling_short = [&counted] {
      return counted.exact_searches_given_up + counted.repeat_searches_given_up +
             counted.pose_gaps_left_open;
    };
    const std::size_t short_before = falling_short();
    const TreeEvaluation evaluation = evaluateIsms(
        poses, estimates_of_object, merged > 0 ? &every_estimate : nullptr, &counted, budget);
    // The best over all labellings is proven only where that of each labelling is.
    complete =
        complete && falling_short() == short_before && searchesReachTheExhaustiveBest(merged > 0);
    RootResults chosen = rootResultsToAssemble(evaluation);
    TreeEvaluation over_fewer_objects;
    if (falling_short() > short_before &&
        searchObjectSubsets(poses, estimates_of_object, every_estimate, evaluation, counted,
                            over_fewer_objects))
      preferBestOf(over_fewer_objects, chosen);
    for (const auto& [evaluated, r] : chosen) {
      SceneInstance instance = assembleInstance(*evaluated, r, poses, estimates_of_object);
      instance.ids_ignored = matching.ids_ignored;
      // One labelling cannot repeat an instance; only across labellings can one reappear.
      const bool known =
          labelling > 0 && std::any_of(instances.begin(), instances.end(), [&](const auto& other) {
            return sameInstance(other, instance);
          });
      if (!known)
        instances.push_back(std::move(instance));
    }
  }
  counted.exact_search_comparisons = budget.comparisons_used;
  counted.exact_search_votes = budget.votes_used;
  counted.pose_steps = budget.pose_steps_used;
  counted.search_complete = complete;
  for (SceneInstance& instance : instances)
    instance.search_complete = complete;
  // Best first; the root's order (which breaks ties by the model) within one labelling.
  std::stable_sort(instances.begin(), instances.end(), [](const auto& a, const auto& b) {
    return a.confidence > b.confidence + 1e-12;
  });
  return instances;
}

}  // namespace asr_ism_tree
