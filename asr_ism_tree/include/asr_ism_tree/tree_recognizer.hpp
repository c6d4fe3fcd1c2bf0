#pragma once

#include <cstddef>
#include <limits>
#include <vector>

#include "asr_ism/ism_recognizer.hpp"
#include "asr_ism/thread_pool.hpp"
#include "asr_ism_tree/ism_tree.hpp"
#include "asr_ism_tree/scene_instance.hpp"

namespace asr_ism_tree {

struct TreeRecognitionParameters {
  /// How many of a sub-ISM's best results are passed up to its parent as placeholder estimates.
  /// The cap keeps the combinations in the parent from exploding; results of one ISM that match
  /// the same inputs are merged before the cap, so several distinct hypotheses get through.
  std::size_t results_passed_up = 4;
  /// Larger configurations are refused with an InputError, so that one request cannot hold a
  /// caller (a node's service, its continuous output) for long.
  std::size_t max_estimates = 10000;
  /// Estimates without a known id are matched by type; where a type has several objects in the
  /// scene, each assignment of such estimates to objects is recognised and the best instances
  /// kept. More assignments than this are refused with an InputError.
  std::size_t max_labellings = 64;
  /// Estimates of one object within the support radius and the maximum angle deviation of one
  /// another are one detection seen again (repeated_detections.hpp): each such group enters
  /// recognition as one estimate, so recognition time grows linearly with repeated detections
  /// instead of with the cube of their number. false: every estimate enters (the exhaustive
  /// search, with which every combination of repeated detections is tried).
  bool merge_repeated_detections = true;
  /// With `exact_best`, where repeated detections were merged: the exact search asks whether any
  /// combination of every estimate beats the best over the representatives, so the best
  /// instance is that of every estimate, within the exact search's limits
  /// (TreeRecognitionStats::repeat_searches_given_up says where they ran out). It starts from
  /// the repeats that fit the merged best instance best (best_fitting_repeats.hpp), which may
  /// reach the bound, so that nothing need be searched. false: the best over the
  /// representatives, which can be lower (docs/recognition.md).
  bool exact_over_repeats = true;
  /// Makes the best instance that of the exhaustive search (`pass_every_result`): after the first
  /// evaluation, every sub-ISM is asked for every further result that could still be part of a
  /// better instance (exact_best_search.hpp). Seeing an object badly then never scores lower than
  /// not seeing it. false: the best instance of the `results_passed_up` best results alone.
  bool exact_best = true;
  /// The exact search gives up (and the first evaluation's best stands) where it would cast more
  /// votes than this in one ISM: near-duplicate results of sub-ISMs that all could still matter
  /// multiply up the tree. TreeRecognitionStats::exact_searches_given_up counts such cases.
  /// (5,000 before the vote search skipped votes below its floor, 20,000 before the ISM search
  /// binned votes in a frame taken from its inputs. Since then its work, and so whether the
  /// comparisons cap below decides, does not depend on where the world frame lies, and the caps
  /// below bound the work whatever this is. 60,000: on topology selection's test configurations
  /// (`asr bench exact`, 2,000) the search gives up in 573 instead of 704, raising the best in
  /// 156 more (gedeck by up to 0.020, Gedeck_Ende 0.035); 100,000 gives up in 3 fewer at 1.2-1.6
  /// times gedeck's mean time. docs/recognition.md.)
  std::size_t exact_search_max_votes = 60000;
  /// ... and where, over all its ISMs (and every assignment of id-less estimates), it would make
  /// more vote-to-hypothesis comparisons than this in one recognition: the bound on its work, so
  /// that no input can hold a caller for long (20-50 ns per comparison on the 2-core development
  /// machine, so at most 0.1-0.25 s; `asr bench exact`, docs/recognition.md). A count, not a
  /// clock: the outcome does not depend on the machine or its load.
  std::size_t exact_search_max_comparisons = 5000000;
  /// ... and where it would cast more votes than this over all its ISM evaluations (and
  /// assignments) in one recognition: casting, binning and gathering a vote cost about 2 us on
  /// the development machine (0.2 s for all), which the comparisons do not count. With both
  /// caps one recognition's exact search stays below about 0.5 s (docs/recognition.md).
  std::size_t exact_search_max_total_votes = 100000;
  /// ... and the poses of child results a parent hypothesis may sit at (the pose gap,
  /// exact_best_search.hpp) are sought with at most this many pose compositions in one
  /// recognition. Beyond it the search goes on without them, and its best may fall short of the
  /// exhaustive search's (TreeRecognitionStats::pose_gaps_left_open).
  std::size_t exact_search_max_pose_steps = 1000000;
  /// Where the exact search gives up: 0 (default), the first best stands unchecked. n > 0: an
  /// upper bound of the exhaustive search's best is computed with at most n comparisons
  /// (relaxed_tree_bound.hpp); where it is the first best, that best is proven (counted in
  /// `exact_searches_proven_by_bound`, not as given up), elsewhere it bounds the shortfall
  /// (`largest_possible_shortfall`). Off by default: on the kitchen recordings, where the search
  /// gives up, the bound either needs more than 30 million comparisons (about 1 s) or is too
  /// loose to prove anything (docs/recognition.md).
  std::size_t relaxed_bound_max_work = 0;
  /// Where the exact search gives up: n > 0, the tree is evaluated once more with each sub-ISM
  /// passing up n results that are diverse in pose (the best first, none within 10 % of the
  /// support radius and of the maximum angle deviation of a better one), so that a hypothesis
  /// away from where a badly seen object pulls the best ones reaches the parent; the better of
  /// both bests stands (both are instances of the input, so the answer can only rise). 0: off.
  std::size_t diverse_results_passed_up = 32;
  /// That second evaluation is abandoned (the first best stands) beyond this many
  /// vote-to-hypothesis comparisons; votes are capped as in the exact search, so it adds at most
  /// about as much time as the exact search may take.
  std::size_t diverse_max_comparisons = 5000000;
  /// Where the search over every seen object gave up or completed with the pose gap open (its
  /// best may then fall short of the exhaustive one): further recognitions with seen objects
  /// left out (object_subsets.hpp), the best of all standing, so that the answer is at least
  /// that with any object removed (seeing an object badly never scores lower than not seeing
  /// it). Subsets that cannot beat the best found (by their number of leaves) or that lie
  /// within one whose search completed are not recognised; each recognition has the budgets
  /// above, so its best is that of the configuration without the other objects. No further
  /// subset is recognised once their work reaches this in all: vote-to-hypothesis comparisons
  /// and pose-gap steps count 1 each, a vote cast 50 (casting, binning and gathering one costs
  /// about 2 us on the development machine, a comparison or step 20-50 ns), so the cap is about
  /// 0.4-1 s plus one subset's recognition (TreeRecognitionStats::object_subset_searches_cut:
  /// only there may the answer fall below that with some object removed). 0: off.
  std::size_t object_subsets_max_work = 20000000;
  /// Every sub-ISM passes every result up (of results at one pose, the best): the exhaustive
  /// search, slow beyond small scenes; what the exact search is tested against.
  bool pass_every_result = false;
};

struct EvaluatedIsm;
struct TreeEvaluation;
struct ExactSearchBudget;

struct TreeRecognitionStats {
  asr_ism::IsmRecognitionStats isms;  // summed over the tree's ISMs
  std::size_t root_results = 0;
  std::size_t merged_estimates = 0;         // repeated detections left out, summed over labellings
  std::size_t exact_searches_given_up = 0;  // over labellings
  /// Searches over every repeated detection given up (over labellings): there the best over the
  /// representatives stands, and may fall short of the exhaustive search's.
  std::size_t repeat_searches_given_up = 0;
  /// Where repeated detections were merged (over labellings): the evaluations over the repeats
  /// that fit the merged best instance best that beat it, and of those the ones that reached the
  /// bound (every seen leaf matched fully: the exhaustive search's best, nothing searched).
  std::size_t fitted_repeats_better = 0;
  std::size_t fitted_repeats_at_bound = 0;
  std::size_t exact_search_comparisons = 0;  // spent by the exact search (within isms as well)
  std::size_t exact_search_votes = 0;        // cast by the exact search (within isms as well)
  /// Exact searches (over labellings, first and over repeats) that completed without every
  /// pose a better hypothesis could sit at (exact_search_max_pose_steps ran out): their best
  /// stands but may fall short of the exhaustive search's.
  std::size_t pose_gaps_left_open = 0;
  std::size_t pose_steps = 0;  // pose compositions spent closing the gap
  /// Searches that ran out of budget but whose best the relaxed bound (relaxed_tree_bound.hpp)
  /// proved to be the exhaustive search's: not counted as given up.
  std::size_t exact_searches_proven_by_bound = 0;
  /// Where searches were given up, the most (in confidence) by which the best instance can fall
  /// short of the exhaustive search's, as the relaxed bound shows; infinity where it ran out too.
  double largest_possible_shortfall = 0.0;
  std::size_t relaxed_bound_work = 0;  // comparisons and votes of the relaxed bounds
  /// Second evaluations with pose-diverse results where the exact search gave up (over
  /// labellings), those whose best beat the first evaluation's, those abandoned at their
  /// budget, and their comparisons.
  std::size_t diverse_evaluations = 0;
  std::size_t diverse_evaluations_better = 0;
  std::size_t diverse_evaluations_given_up = 0;
  std::size_t diverse_comparisons = 0;
  /// Recognitions of subsets of the seen objects where the search over all gave up or left the
  /// pose gap open (over labellings), those whose best beat it, the labellings where
  /// `object_subsets_max_work` ran out before every subset that could beat the best was
  /// recognised (there the answer may fall below that with some object removed), and the work
  /// those recognitions made (as `object_subsets_max_work` counts it).
  std::size_t object_subset_searches = 0;
  std::size_t object_subsets_better = 0;
  std::size_t object_subset_searches_cut = 0;
  std::size_t object_subset_work = 0;
  /// Every search completed within its limits for every assignment of id-less estimates, so the
  /// best instance is the exhaustive search's (SceneInstance::search_complete).
  bool search_complete = false;
};

/// Recognises the scene a tree models (the paper's Algo. 2-4). ISMs are evaluated bottom-up, level
/// by level; the best results of each sub-ISM become placeholder estimates of its parent, weighted
/// by their objective. Every result of the root is then assembled top-down, following the
/// explicit links from placeholder matches to the child results they came from, into a scene
/// instance. The ISMs of one level run in parallel on the pool. Every input carries the real
/// estimates it stands for, so the root drops results whose estimates are a subset of a better
/// result's: each instance found uses some estimate that no better instance uses.
/// The input order does not matter (estimates are sorted first); the output is deterministic
/// whatever the pool's size. Clutter (objects the scene does not know) is ignored; repeated
/// detections of one object (within the support radius and the maximum angle deviation) enter
/// as one estimate each (TreeRecognitionParameters::merge_repeated_detections).
class TreeRecognizer {
 public:
  /// The tree (and the pool, if given) must outlive the recognizer.
  explicit TreeRecognizer(const IsmTree& tree, TreeRecognitionParameters parameters = {},
                          asr_ism::ThreadPool* pool = nullptr);

  /// Instances sorted by confidence, best first. Estimates match scene objects by type and id; an
  /// estimate without an id, or with an id the scene does not know for its type, may stand for
  /// any object of its type (the best assignment wins, several estimates of one object count
  /// once, and every instance says `ids_ignored`). Every instance says `search_complete`: whether
  /// the best is proven to be the exhaustive search's. Throws InputError for a non-finite pose
  /// and for more estimates or assignments than the parameters allow.
  std::vector<SceneInstance> recognize(const asr_common::Configuration& configuration,
                                       TreeRecognitionStats* stats = nullptr) const;

  const IsmTree& tree() const { return tree_; }

 private:
  // Whether the parameters make the best of one labelling the exhaustive search's wherever no
  // search runs out (`merged`: repeated detections were merged).
  bool searchesReachTheExhaustiveBest(bool merged) const;
  struct Leaf {
    int ism;
    int member;
    int object;  // index in tree.objects()
  };

  void evaluateIsm(int ism, double from, std::vector<EvaluatedIsm>& evaluated,
                   const std::vector<Pose>& poses,
                   const std::vector<std::vector<int>>& estimates_of_object,
                   asr_ism::IsmRecognitionStats& stats, ExactSearchBudget* budget = nullptr,
                   std::size_t diverse = 0, const std::vector<double>* member_from = nullptr) const;
  // Where the exact search gave up: evaluates the tree into `evaluated` with pose-diverse
  // results passed up (TreeRecognitionParameters::diverse_results_passed_up). True if its root
  // holds a result better than `first_best`.
  bool evaluateDiversely(std::vector<EvaluatedIsm>& evaluated, double first_best,
                         const std::vector<Pose>& poses,
                         const std::vector<std::vector<int>>& estimates_of_object,
                         std::vector<asr_ism::IsmRecognitionStats>& ism_stats,
                         TreeRecognitionStats* stats) const;
  // The first evaluation: each sub-ISM passes its few best results up; the root keeps only
  // results reaching `root_at_least` (a caller after a better best skips everything else).
  void evaluateFirst(const std::vector<Pose>& poses,
                     const std::vector<std::vector<int>>& estimates_of_object,
                     std::vector<EvaluatedIsm>& evaluated,
                     std::vector<asr_ism::IsmRecognitionStats>& ism_stats,
                     double root_at_least = -std::numeric_limits<double>::infinity()) const;
  // The leaves whose object has an estimate: the most the root's objective can reach.
  double seenLeaves(const std::vector<std::vector<int>>& estimates_of_object) const;
  // Where repeated detections were merged: the tree evaluated over the repeats that fit the best
  // instance of `first` best (best_fitting_repeats.hpp) into `fitted`, in rounds while the best
  // rises. True if its best beats the first's; it is then a lower bound of the exhaustive
  // search's best that is often that best itself.
  bool evaluateBestFittingRepeats(const std::vector<EvaluatedIsm>& first,
                                  const std::vector<Pose>& poses,
                                  const std::vector<std::vector<int>>& representatives,
                                  const std::vector<std::vector<int>>& every_estimate,
                                  std::vector<asr_ism::IsmRecognitionStats>& ism_stats,
                                  std::vector<EvaluatedIsm>& fitted) const;
  // `with_repeats`: every estimate per object where `estimates_of_object` are the
  // representatives of repeated detections, nullptr where nothing was merged. The exact
  // searches seek only instances beating `known_best` (one found over other estimates).
  TreeEvaluation evaluateIsms(const std::vector<Pose>& poses,
                              const std::vector<std::vector<int>>& estimates_of_object,
                              const std::vector<std::vector<int>>* with_repeats,
                              TreeRecognitionStats* stats, ExactSearchBudget& budget,
                              double known_best = 0.0) const;
  // The exact search (exact_best_search.hpp) from the results in `evaluated`, which are those of
  // a first evaluation over `estimates_of_object` or, `from_lower_bounds`, over a subset of them.
  // Only root results beyond `known_best` (an instance found over other estimates) are sought.
  // True if the root holds its results (none: nothing beats `known_best`); false where nothing
  // could be better or the budget ran out (counted in `given_up`).
  bool searchExactly(std::vector<EvaluatedIsm>& evaluated, bool from_lower_bounds,
                     double known_best, const std::vector<Pose>& poses,
                     const std::vector<std::vector<int>>& estimates_of_object,
                     std::vector<asr_ism::IsmRecognitionStats>& ism_stats,
                     ExactSearchBudget& budget, TreeRecognitionStats* stats,
                     std::size_t TreeRecognitionStats::*given_up) const;
  // Where the search over every seen object gave up in `evaluation`: the evaluation of the
  // subset of the seen objects whose best beats it most (object_subsets.hpp) into `better`;
  // false if none does. `estimates_of_object`: the representatives of repeated detections,
  // `every_estimate`: all.
  bool searchObjectSubsets(const std::vector<Pose>& poses,
                           const std::vector<std::vector<int>>& estimates_of_object,
                           const std::vector<std::vector<int>>& every_estimate,
                           const TreeEvaluation& evaluation, TreeRecognitionStats& stats,
                           TreeEvaluation& better) const;
  // Per object, one estimate for each group of repeated detections; returns how many were left
  // out.
  std::size_t mergeRepeated(std::vector<std::vector<int>>& estimates_of_object,
                            const std::vector<Pose>& poses) const;
  SceneInstance assembleInstance(const std::vector<EvaluatedIsm>& evaluated,
                                 std::size_t root_result, const std::vector<Pose>& poses,
                                 const std::vector<std::vector<int>>& estimates_of_object) const;

  const IsmTree& tree_;
  TreeRecognitionParameters parameters_;
  asr_ism::ThreadPool* pool_;
  std::vector<std::vector<int>> levels_;  // ISM indices per level, deepest level first
  std::vector<int> bottom_up_;            // the levels in that order
  std::vector<Leaf> leaves_;
};

}  // namespace asr_ism_tree
