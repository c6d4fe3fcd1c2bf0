// Recognising subsets of the seen objects where the search over all gave up
// (object_subsets.hpp): which subsets are visited, and that seeing an object badly then never
// scores lower than not seeing it, however small the search's budget.

#include <gtest/gtest.h>

#include <iostream>
#include <map>
#include <random>
#include <set>
#include <string>

#include "../src/object_subsets.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"
#include "instance_lookup.hpp"
#include "random_perturbation.hpp"
#include "synthetic_scene.hpp"

namespace asr_ism_tree {
namespace {

using asr_common::Configuration;

double leavesIn(ObjectSet subset, const std::vector<int>& leaf_objects) {
  double count = 0.0;
  for (int object : leaf_objects)
    count += ((subset >> object) & 1U) != 0U ? 1.0 : 0.0;
  return count;
}

// The bound of a subset: its number of leaves.
ObjectSubsetSearch::Bound leavesOf(std::vector<int> leaf_objects) {
  return [leaf_objects](ObjectSet subset) { return leavesIn(subset, leaf_objects); };
}

TEST(ObjectSubsetSearch, NothingIsVisitedThatCannotBeatTheBest) {
  const auto one_leaf_each = leavesOf({0, 1, 2});
  EXPECT_FALSE(ObjectSubsetSearch(one_leaf_each, 0b111, 2.5, false).next());
  // Where the search over every seen object completed, no subset can do better.
  EXPECT_FALSE(ObjectSubsetSearch(one_leaf_each, 0b111, 0.0, true).next());
}

TEST(ObjectSubsetSearch, VisitsByFallingBoundAndSkipsWhatACompletedSearchCovers) {
  // Object 0 in three leaves, 1 and 2 in one each: leaving out 1 or 2 leaves four leaves.
  ObjectSubsetSearch search(leavesOf({0, 0, 0, 1, 2}), 0b111, 1.5, false);
  EXPECT_EQ(search.next(), ObjectSet{0b101});  // of equal bounds, the larger set first
  search.report(0b101, 1.0, true);             // completed: {0} and {2} need nothing more
  EXPECT_EQ(search.next(), ObjectSet{0b011});
  // Gave up at 2: {0} is covered, {1} and {1, 2} (one and two leaves) cannot beat 2.
  search.report(0b011, 2.0, false);
  EXPECT_FALSE(search.next());
  EXPECT_EQ(search.best(), 2.0);
}

TEST(ObjectSubsetSearch, EverySubsetThatCouldBeatTheBestIsVisitedOrCovered) {
  // Random trees and outcomes: in the end every subset of the seen objects was visited once, or
  // cannot beat the best, or lies within a visited subset whose search completed.
  std::mt19937 random(3);
  for (int trial = 0; trial < 300; ++trial) {
    const int objects = std::uniform_int_distribution<int>(1, 7)(random);
    std::vector<int> leaf_objects;
    for (int leaf = 0; leaf < 2 * objects; ++leaf)
      leaf_objects.push_back(std::uniform_int_distribution<int>(0, objects - 1)(random));
    const ObjectSet seen = std::uniform_int_distribution<ObjectSet>(1, (1U << objects) - 1)(random);
    std::map<ObjectSet, std::pair<double, bool>> outcome;  // reached, completed
    const auto outcomeOf = [&](ObjectSet subset) {
      if (!outcome.count(subset)) {
        const double reached = std::uniform_real_distribution<double>(0.0, 1.0)(random) *
                               leavesIn(subset, leaf_objects);
        outcome[subset] = {reached, std::uniform_int_distribution<int>(0, 2)(random) == 0};
      }
      return outcome[subset];
    };
    const double first = 0.5 * std::uniform_real_distribution<double>(0.0, 1.0)(random) *
                         leavesIn(seen, leaf_objects);
    ObjectSubsetSearch search(leavesOf(leaf_objects), seen, first, false);
    std::set<ObjectSet> visited, completed;
    double best = first;
    while (const auto subset = search.next()) {
      EXPECT_EQ((*subset & ~seen), 0U);
      EXPECT_TRUE(visited.insert(*subset).second) << "visited twice";
      EXPECT_GT(leavesIn(*subset, leaf_objects), best);
      const auto [reached, done] = outcomeOf(*subset);
      best = std::max(best, reached);
      if (done)
        completed.insert(*subset);
      search.report(*subset, reached, done);
    }
    EXPECT_EQ(search.best(), best);
    for (ObjectSet subset = 0; subset < seen; ++subset) {
      if ((subset & ~seen) != 0U || visited.count(subset) != 0)
        continue;
      const bool covered = std::any_of(completed.begin(), completed.end(),
                                       [&](ObjectSet done) { return (subset & ~done) == 0U; });
      EXPECT_TRUE(covered || leavesIn(subset, leaf_objects) <= best + 1e-9)
          << "trial " << trial << ": subset " << subset << " of " << seen << " left out";
    }
  }
}

// Five objects of a synthetic table in star, complete and chain trees.
class SubsetsInATree : public ::testing::Test {
 protected:
  SubsetsInATree() : demonstration_(synthetic::demonstration("table", kObjects, 6)) {
    RelationTopology chain(kObjects);
    for (std::size_t i = 0; i + 1 < kObjects.size(); ++i)
      chain.addRelation(i, i + 1);
    trees_.emplace_back("star",
                        generateIsmTree(demonstration_, RelationTopology::star(kObjects, 0), {}));
    trees_.emplace_back("complete",
                        generateIsmTree(demonstration_, RelationTopology::complete(kObjects), {}));
    trees_.emplace_back("chain", generateIsmTree(demonstration_, chain, {}));
  }

  inline static const std::vector<asr_common::ObjectKey> kObjects = {
      {"Plate", "1"}, {"Cup", "1"}, {"Knife", "1"}, {"Fork", "1"}, {"Spoon", "1"}};
  asr_ism::Demonstration demonstration_;
  std::vector<std::pair<std::string, IsmTree>> trees_;
};

TEST_F(SubsetsInATree, SeeingAnObjectBadlyNeverScoresLowerThanNotSeeingItWhereSearchesRunOut) {
  // Budgets so small that the exact search gives up in most cases, and no pose-diverse
  // evaluation: with the subsets recognised too, the object seen badly never scores lower than the
  // object removed, wherever `object_subsets_max_work` sufficed; without them, it does
  // somewhere.
  TreeRecognitionParameters small_budget;
  small_budget.exact_search_max_comparisons = 300;
  small_budget.diverse_results_passed_up = 0;  // else it hides the first best's shortfalls here
  TreeRecognitionParameters without_subsets = small_budget;
  without_subsets.object_subsets_max_work = 0;
  TreeRecognitionParameters one_subset = small_budget;
  one_subset.object_subsets_max_work = 1;
  std::mt19937 random(17);
  int given_up = 0, cut = 0, raised = 0, lower_without = 0, cut_after_one = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const auto [changed, removed, what] = test_support::oneObjectSeenBadly(demonstration_, random);
    for (const auto& [name, tree] : trees_) {
      SCOPED_TRACE(name + ", case " + std::to_string(trial) + ": " + what);
      TreeRecognitionStats stats;
      const TreeRecognizer recognizer(tree, small_budget);
      const double with = bestConfidence(recognizer.recognize(changed, &stats));
      const double without = bestConfidence(recognizer.recognize(removed));
      given_up += stats.exact_searches_given_up > 0 ? 1 : 0;
      cut += static_cast<int>(stats.object_subset_searches_cut);
      raised += stats.object_subsets_better > 0 ? 1 : 0;
      // Past its comparisons, no further subset is recognised.
      TreeRecognitionStats one_stats;
      TreeRecognizer(tree, one_subset).recognize(changed, &one_stats);
      EXPECT_LE(one_stats.object_subset_searches, 1u);
      cut_after_one += static_cast<int>(one_stats.object_subset_searches_cut);
      if (stats.object_subset_searches_cut == 0) {
        EXPECT_GE(with, without - 1e-9);
      }
      const TreeRecognizer plain(tree, without_subsets);
      lower_without +=
          bestConfidence(plain.recognize(changed)) < bestConfidence(plain.recognize(removed)) - 1e-9
              ? 1
              : 0;
      // Every instance is one of the input, so never above the exhaustive search's best.
      TreeRecognitionParameters exhaustive;
      exhaustive.pass_every_result = true;
      EXPECT_LE(with, bestConfidence(TreeRecognizer(tree, exhaustive).recognize(changed)) + 1e-9);
    }
  }
  std::cout << "budget of 300 comparisons: the search gave up in " << given_up
            << " recognitions with the object seen; subsets raised the best in " << raised
            << ", ran out in " << cut << "; without subsets the object seen scored lower in "
            << lower_without << "\n";
  EXPECT_GT(given_up, 100);
  EXPECT_GT(lower_without, 0);
  EXPECT_EQ(cut, 0);
  EXPECT_GT(cut_after_one, 0);
}

TEST_F(SubsetsInATree, AreRecognisedWhereASearchCompletesWithThePoseGapOpen) {
  // One pose step: every search that completes leaves the pose gap open (its best may fall short
  // of the exhaustive one), and none gives up, so only the open gap can call for the subsets.
  TreeRecognitionParameters one_pose_step;
  one_pose_step.exact_search_max_pose_steps = 1;
  one_pose_step.diverse_results_passed_up = 0;
  std::mt19937 random(17);
  int gaps_open = 0, given_up = 0, with_subsets = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const auto [changed, removed, what] = test_support::oneObjectSeenBadly(demonstration_, random);
    for (const auto& [name, tree] : trees_) {
      SCOPED_TRACE(name + ", case " + std::to_string(trial) + ": " + what);
      TreeRecognitionStats stats;
      const TreeRecognizer recognizer(tree, one_pose_step);
      const double with = bestConfidence(recognizer.recognize(changed, &stats));
      gaps_open += stats.pose_gaps_left_open > 0 ? 1 : 0;
      given_up += static_cast<int>(stats.exact_searches_given_up);
      with_subsets += stats.object_subset_searches > 0 ? 1 : 0;
      EXPECT_EQ(stats.object_subset_searches_cut, 0u);
      EXPECT_GE(with, bestConfidence(recognizer.recognize(removed)) - 1e-9);
    }
  }
  std::cout << "one pose step: the gap stayed open in " << gaps_open << " of 450 recognitions, "
            << with_subsets << " of them recognised subsets\n";
  EXPECT_GT(gaps_open, 100);
  EXPECT_EQ(given_up, 0);
  EXPECT_GT(with_subsets, 0);
}

}  // namespace
}  // namespace asr_ism_tree
