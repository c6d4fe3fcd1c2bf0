// The tree's best instance is that of the exhaustive search (every sub-ISM passing every result
// up), so seeing an object badly never scores lower than not seeing it: seeded random cases of
// small synthetic scenes, in star, complete and chain trees.

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <numeric>
#include <random>
#include <string>

#include "../src/pose_diverse_results.hpp"
#include "../src/relaxed_tree_bound.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"
#include "instance_lookup.hpp"
#include "random_perturbation.hpp"
#include "synthetic_scene.hpp"

namespace asr_ism_tree {
namespace {

using asr_common::Configuration;
using asr_common::Pose;

// A random turn or shift of one pose at a random scale in [0.02, 1], drawn before the turn or
// shift, so every seeded case draws the same numbers as before.
Pose perturbed(const Pose& pose, std::mt19937& random) {
  const double scale = std::uniform_real_distribution<double>(0.02, 1.0)(random);
  return test_support::perturbed(pose, random, scale);
}
// A chain: every object related to the next one only, the deepest tree of the scene.
RelationTopology chain(const std::vector<asr_common::ObjectKey>& objects) {
  RelationTopology topology(objects);
  for (std::size_t i = 0; i + 1 < objects.size(); ++i)
    topology.addRelation(i, i + 1);
  return topology;
}

class ExactSearch : public ::testing::Test {
 protected:
  ExactSearch() : demonstration_(synthetic::demonstration("table", kObjects, 6)) {
    trees_.emplace_back("star",
                        generateIsmTree(demonstration_, RelationTopology::star(kObjects, 0), {}));
    trees_.emplace_back("complete",
                        generateIsmTree(demonstration_, RelationTopology::complete(kObjects), {}));
    trees_.emplace_back("chain", generateIsmTree(demonstration_, chain(kObjects), {}));
  }

  // Every object perturbed with probability 1/2, some removed, the whole set maybe jittered.
  Configuration randomCase(std::mt19937& random) const {
    const std::size_t step =
        std::uniform_int_distribution<std::size_t>(0, demonstration_.stepCount() - 1)(random);
    Configuration configuration;
    for (asr_common::ObjectEstimate estimate : demonstration_.configuration(step)) {
      const int what = std::uniform_int_distribution<int>(0, 5)(random);
      if (what == 0)
        continue;  // not seen
      if (what <= 2)
        estimate.pose = perturbed(estimate.pose, random);
      configuration.push_back(estimate);
    }
    return configuration;
  }

  // Where the search under a small budget gave up, its best is at least the first evaluation's
  // (the pose-diverse evaluation can only raise it) and at most the exact one, as where it
  // completed without the poses of the pose gap; where it completed, the exact one. Counts each
  // outcome.
  struct BudgetOutcomes {
    int given_up = 0, completed = 0, raised = 0, raised_to_exact = 0;
  };
  static void expectFirstBestOrExact(const IsmTree& tree, const Configuration& configuration,
                                     const TreeRecognitionStats& stats, double bounded,
                                     double exact, BudgetOutcomes& outcomes) {
    if (stats.exact_searches_given_up > 0 || stats.pose_gaps_left_open > 0) {
      ++outcomes.given_up;
      TreeRecognitionParameters few;
      few.exact_best = false;
      const double first = bestConfidence(TreeRecognizer(tree, few).recognize(configuration));
      EXPECT_GE(bounded, first);
      EXPECT_LE(bounded, exact + 1e-9);
      outcomes.raised += bounded > first + 1e-9 ? 1 : 0;
      outcomes.raised_to_exact += bounded > first + 1e-9 && bounded > exact - 1e-9 ? 1 : 0;
    } else {
      ++outcomes.completed;
      EXPECT_NEAR(bounded, exact, 1e-9);
    }
  }

  inline static const std::vector<asr_common::ObjectKey> kObjects = {
      {"Plate", "1"}, {"Cup", "1"}, {"Knife", "1"}, {"Fork", "1"}, {"Spoon", "1"}};
  asr_ism::Demonstration demonstration_;
  std::vector<std::pair<std::string, IsmTree>> trees_;
};

TreeRecognitionParameters exhaustive() {
  TreeRecognitionParameters parameters;
  parameters.pass_every_result = true;
  return parameters;
}

TEST_F(ExactSearch, BestInstanceIsThatOfTheExhaustiveSearch) {
  std::mt19937 random(5);
  for (int trial = 0; trial < 150; ++trial) {
    const Configuration configuration = randomCase(random);
    for (const auto& [name, tree] : trees_) {
      const auto exact = TreeRecognizer(tree).recognize(configuration);
      const auto all = TreeRecognizer(tree, exhaustive()).recognize(configuration);
      ASSERT_EQ(exact.empty(), all.empty()) << name << ", case " << trial;
      EXPECT_NEAR(bestConfidence(exact), bestConfidence(all), 1e-9) << name << ", case " << trial;
    }
  }
}

TEST_F(ExactSearch, SeeingAnObjectBadlyNeverScoresLowerThanNotSeeingIt) {
  std::mt19937 random(6);
  for (int trial = 0; trial < 150; ++trial) {
    const Configuration configuration = randomCase(random);
    if (configuration.empty())
      continue;
    const std::size_t object =
        std::uniform_int_distribution<std::size_t>(0, configuration.size() - 1)(random);
    Configuration removed = configuration;
    removed.erase(removed.begin() + object);
    Configuration changed = configuration;
    changed[object].pose = perturbed(configuration[object].pose, random);
    for (const auto& [name, tree] : trees_) {
      const TreeRecognizer recognizer(tree);
      EXPECT_GE(bestConfidence(recognizer.recognize(changed)),
                bestConfidence(recognizer.recognize(removed)) - 1e-9)
          << name << ", case " << trial;
    }
  }
}

TEST_F(ExactSearch, WithoutTheExactSearchATreeCanFallShort) {
  // What the exact search adds: over these cases, the few best results per sub-ISM alone miss
  // the exhaustive search's best instance somewhere, and never exceed it.
  TreeRecognitionParameters few;
  few.exact_best = false;
  std::mt19937 random(5);
  double largest_shortfall = 0.0;
  for (int trial = 0; trial < 150; ++trial) {
    const Configuration configuration = randomCase(random);
    for (const auto& [name, tree] : trees_) {
      const double all =
          bestConfidence(TreeRecognizer(tree, exhaustive()).recognize(configuration));
      const double heuristic = bestConfidence(TreeRecognizer(tree, few).recognize(configuration));
      EXPECT_LE(heuristic, all + 1e-9) << name << ", case " << trial;
      largest_shortfall = std::max(largest_shortfall, all - heuristic);
    }
  }
  std::cout << "few results per sub-ISM: largest shortfall " << largest_shortfall << "\n";
  EXPECT_GT(largest_shortfall, 1e-6);
}

TEST_F(ExactSearch, WorkIsBoundedAndWhereItRunsOutTheFirstBestStands) {
  // With a small budget of comparisons, the search gives up within it wherever it needs more,
  // and the answer is then the first evaluation's; where it stays within, the exact one.
  TreeRecognitionParameters small_budget;
  small_budget.exact_search_max_comparisons = 2000;
  std::mt19937 random(7);
  BudgetOutcomes outcomes;
  for (int trial = 0; trial < 150; ++trial) {
    const Configuration configuration = randomCase(random);
    for (const auto& [name, tree] : trees_) {
      SCOPED_TRACE(name + ", case " + std::to_string(trial));
      TreeRecognitionStats stats;
      const double bounded =
          bestConfidence(TreeRecognizer(tree, small_budget).recognize(configuration, &stats));
      EXPECT_LE(stats.exact_search_comparisons, small_budget.exact_search_max_comparisons);
      const double exact = bestConfidence(TreeRecognizer(tree).recognize(configuration));
      expectFirstBestOrExact(tree, configuration, stats, bounded, exact, outcomes);
    }
  }
  EXPECT_GT(outcomes.given_up, 0);
  EXPECT_GT(outcomes.completed, 0);
}

TEST_F(ExactSearch, EveryInstanceSaysWhetherTheBestIsTheExhaustiveSearchs) {
  // `search_complete` is said exactly where no search ran out and the parameters make the best
  // exact (a tree's sub-ISMs passing up their few best results alone do not); where it is said,
  // the best is the exhaustive search's; where not, the best may fall short, and does in some
  // cases, so a robot must not take such a confidence for the scene's.
  TreeRecognitionParameters small_budget, few;
  small_budget.exact_search_max_comparisons = 2000;
  few.exact_best = false;
  std::mt19937 random(8);
  int complete = 0, incomplete = 0, short_of_exhaustive = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const Configuration configuration = randomCase(random);
    for (const auto& [name, tree] : trees_) {
      const auto all = TreeRecognizer(tree, exhaustive()).recognize(configuration);
      for (const auto& [parameters, what] :
           {std::make_pair(TreeRecognitionParameters{}, "default"),
            std::make_pair(small_budget, "small budget"), std::make_pair(few, "few results")}) {
        SCOPED_TRACE(name + ", " + what + ", case " + std::to_string(trial));
        TreeRecognitionStats stats;
        const auto instances = TreeRecognizer(tree, parameters).recognize(configuration, &stats);
        ASSERT_EQ(instances.empty(), all.empty());
        if (instances.empty())
          continue;
        EXPECT_TRUE(all.front().search_complete);
        const bool ran_out = stats.exact_searches_given_up + stats.repeat_searches_given_up +
                                 stats.pose_gaps_left_open >
                             0;
        const bool few_results = !parameters.exact_best && tree.isms.size() > 1;
        EXPECT_EQ(stats.search_complete, !ran_out && !few_results);
        for (const SceneInstance& instance : instances)
          EXPECT_EQ(instance.search_complete, stats.search_complete);
        if (stats.search_complete) {
          ++complete;
          EXPECT_NEAR(instances.front().confidence, all.front().confidence, 1e-9);
        } else {
          ++incomplete;
          EXPECT_LE(instances.front().confidence, all.front().confidence + 1e-9);
          short_of_exhaustive +=
              instances.front().confidence < all.front().confidence - 1e-9 ? 1 : 0;
        }
      }
    }
  }
  std::cout << "search complete in " << complete << " recognitions, not in " << incomplete
            << ", of which " << short_of_exhaustive << " fell short of the exhaustive best\n";
  EXPECT_GT(complete, 0);
  EXPECT_GT(short_of_exhaustive, 0);
}

TEST_F(ExactSearch, WhereItRunsOutThePoseDiverseEvaluationOnlyRaisesTheBest) {
  // Under a small budget the exact search gives up often. Without the pose-diverse evaluation the
  // first best stands; with it, the best is never lower than that, never above the exhaustive
  // search's, and reaches the exhaustive search's in most cases the first evaluation misses.
  TreeRecognitionParameters small_budget;
  small_budget.exact_search_max_comparisons = 300;
  small_budget.object_subsets_max_work = 0;  // the pose-diverse evaluation alone
  TreeRecognitionParameters without_diverse = small_budget;
  without_diverse.diverse_results_passed_up = 0;
  TreeRecognitionParameters few;
  few.exact_best = false;
  std::mt19937 random(13);
  int given_up = 0, raised = 0, reached = 0, first_short = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const Configuration configuration = randomCase(random);
    for (const auto& [name, tree] : trees_) {
      SCOPED_TRACE(name + ", case " + std::to_string(trial));
      TreeRecognitionStats stats;
      const double diverse =
          bestConfidence(TreeRecognizer(tree, small_budget).recognize(configuration, &stats));
      if (stats.exact_searches_given_up == 0)
        continue;
      ++given_up;
      const double first = bestConfidence(TreeRecognizer(tree, few).recognize(configuration));
      const double all =
          bestConfidence(TreeRecognizer(tree, exhaustive()).recognize(configuration));
      EXPECT_EQ(bestConfidence(TreeRecognizer(tree, without_diverse).recognize(configuration)),
                first);
      EXPECT_GE(diverse, first);
      EXPECT_LE(diverse, all + 1e-9);
      EXPECT_EQ(stats.diverse_evaluations, stats.exact_searches_given_up);
      EXPECT_LE(stats.diverse_evaluations_better + stats.diverse_evaluations_given_up,
                stats.diverse_evaluations);
      EXPECT_LE(stats.diverse_comparisons,
                stats.diverse_evaluations * small_budget.diverse_max_comparisons);
      first_short += first < all - 1e-9 ? 1 : 0;
      raised += diverse > first + 1e-9 ? 1 : 0;
      reached += first < all - 1e-9 && diverse > all - 1e-9 ? 1 : 0;
    }
  }
  std::cout << "small budget: gave up in " << given_up << " cases, the first best short in "
            << first_short << ", raised by the pose-diverse evaluation in " << raised
            << ", to the exhaustive best in " << reached << "\n";
  EXPECT_GT(given_up, 0);
  // Measured: 125 of the 149 cases the first evaluation misses (diverse_results_passed_up 32).
  EXPECT_GT(2 * reached, first_short);
}

TEST(PoseDiverseResults, KeepsTheBestOfEachNeighbourhoodInOrderUpToTheCount) {
  // Results best first along x, 3 mm apart, every third one turned by 30 deg: within 10 mm and
  // 10 deg of a better one kept, a result is dropped.
  std::vector<asr_ism::IsmResult> results;
  for (int i = 0; i < 12; ++i) {
    asr_ism::IsmResult result;
    result.reference_pose.position = Eigen::Vector3d(0.003 * i, 0.0, 0.0);
    result.reference_pose.orientation = Eigen::Quaterniond(
        Eigen::AngleAxisd(i % 3 == 2 ? 30 * M_PI / 180 : 0.0, Eigen::Vector3d::UnitZ()));
    result.objective = 12.0 - i;
    results.push_back(result);
  }
  const double radius = 0.01, angle = 10 * M_PI / 180;
  const auto kept = poseDiverseResults(results, 100, radius, angle);
  // Upright: 0, 4 (12 mm from 0), 9 (15 mm from 4); turned: 2, 8 (18 mm from 2; 5 and 11 are
  // 9 mm from a turned one kept).
  std::vector<double> objectives;
  for (const auto& result : kept)
    objectives.push_back(result.objective);
  EXPECT_EQ(objectives, (std::vector<double>{12, 10, 8, 4, 3}));
  for (std::size_t a = 0; a < kept.size(); ++a) {
    for (std::size_t b = a + 1; b < kept.size(); ++b) {
      const bool near =
          (kept[a].reference_pose.position - kept[b].reference_pose.position).norm() <= radius &&
          asr_common::angleBetween(kept[a].reference_pose.orientation,
                                   kept[b].reference_pose.orientation) <= angle;
      EXPECT_FALSE(near) << a << " " << b;
    }
  }
  EXPECT_EQ(poseDiverseResults(results, 2, radius, angle).size(), 2u);
  EXPECT_TRUE(poseDiverseResults({}, 5, radius, angle).empty());
}

TEST_F(ExactSearch, VotesCastOverTheWholeRecognitionAreBounded) {
  // The total of votes cast by the exact search, over all its ISM evaluations, stays within its
  // cap; where it runs out, the first evaluation's best stands.
  TreeRecognitionParameters small_budget;
  small_budget.exact_search_max_total_votes = 150;
  std::mt19937 random(9);
  BudgetOutcomes outcomes;
  for (int trial = 0; trial < 100; ++trial) {
    const Configuration configuration = randomCase(random);
    for (const auto& [name, tree] : trees_) {
      SCOPED_TRACE(name + ", case " + std::to_string(trial));
      TreeRecognitionStats stats, unbounded_stats;
      const double bounded =
          bestConfidence(TreeRecognizer(tree, small_budget).recognize(configuration, &stats));
      const double exact =
          bestConfidence(TreeRecognizer(tree).recognize(configuration, &unbounded_stats));
      EXPECT_LE(stats.exact_search_votes, small_budget.exact_search_max_total_votes);
      if (unbounded_stats.exact_search_votes > small_budget.exact_search_max_total_votes) {
        // It ran out: given up, its first best proven by the relaxed bound, or completed without
        // the poses of the pose gap (sought in a second pass).
        EXPECT_GT(stats.exact_searches_given_up + stats.exact_searches_proven_by_bound +
                      stats.pose_gaps_left_open,
                  0u);
      }
      expectFirstBestOrExact(tree, configuration, stats, bounded, exact, outcomes);
    }
  }
  EXPECT_GT(outcomes.given_up, 0);
  EXPECT_GT(outcomes.completed, 0);
}

// The relaxed bound over the estimates of a configuration (objects matched by key).
double relaxedBound(const IsmTree& tree, const Configuration& configuration, double radius,
                    std::size_t* work = nullptr) {
  std::vector<int> bottom_up(tree.isms.size());
  std::iota(bottom_up.begin(), bottom_up.end(), 0);
  std::stable_sort(bottom_up.begin(), bottom_up.end(),
                   [&](int a, int b) { return tree.level[a] > tree.level[b]; });
  std::vector<Pose> poses;
  std::vector<std::vector<int>> estimates_of_object(tree.objects().size());
  for (std::size_t i = 0; i < configuration.size(); ++i) {
    poses.push_back(configuration[i].pose);
    for (std::size_t o = 0; o < tree.objects().size(); ++o) {
      if (tree.objects()[o] == configuration[i].key)
        estimates_of_object[o].push_back(static_cast<int>(i));
    }
  }
  const RelaxedBoundParameters parameters{radius * tree.parameters.supportRadius(),
                                          radius * tree.parameters.max_angle_deviation, 100000000};
  return relaxedRootBound(tree, bottom_up, poses, estimates_of_object, parameters, work).value();
}

TEST_F(ExactSearch, RelaxedBoundIsNeverBelowTheExhaustiveBest) {
  // Grouped finely or coarsely, the relaxed evaluation bounds the exhaustive search's best root
  // objective from above; left without its slack, coarse groups fall below it.
  std::mt19937 random(13);
  double largest_gap = 0.0;
  for (int trial = 0; trial < 60; ++trial) {
    const Configuration configuration = randomCase(random);
    for (const auto& [name, tree] : trees_) {
      const double all =
          bestConfidence(TreeRecognizer(tree, exhaustive()).recognize(configuration)) *
          static_cast<double>(tree.leafCount());
      for (double radius : {0.01, 0.1, 0.3}) {
        const double bound = relaxedBound(tree, configuration, radius);
        EXPECT_GE(bound, all - 1e-9) << name << ", case " << trial << ", radius " << radius;
        largest_gap = std::max(largest_gap, bound - all);
      }
    }
  }
  std::cout << "relaxed bound: at most " << largest_gap << " above the exhaustive best\n";
}

TEST_F(ExactSearch, WhereItRunsOutTheRelaxedBoundProvesOrBoundsTheShortfall) {
  // Searches given up under a small budget: where the relaxed bound proves the first best (not
  // counted as given up), it is the exhaustive search's; elsewhere the best falls short of it
  // by at most the shortfall the bound reports. A bound that left out some slack would fall
  // below the exhaustive best somewhere and fail here.
  TreeRecognitionParameters small_budget;
  small_budget.exact_search_max_comparisons = 300;
  small_budget.relaxed_bound_max_work = 3000000;
  std::mt19937 random(11);
  int proven = 0, given_up = 0;
  double largest_reported = 0.0;
  for (int trial = 0; trial < 150; ++trial) {
    const Configuration configuration = randomCase(random);
    for (const auto& [name, tree] : trees_) {
      SCOPED_TRACE(name + ", case " + std::to_string(trial));
      TreeRecognitionStats stats;
      const double bounded =
          bestConfidence(TreeRecognizer(tree, small_budget).recognize(configuration, &stats));
      const double all =
          bestConfidence(TreeRecognizer(tree, exhaustive()).recognize(configuration));
      proven += static_cast<int>(stats.exact_searches_proven_by_bound);
      given_up += static_cast<int>(stats.exact_searches_given_up);
      EXPECT_LE(stats.relaxed_bound_work, small_budget.relaxed_bound_max_work + 1);
      if (stats.exact_searches_given_up == 0) {
        EXPECT_NEAR(bounded, all, 1e-9);
      } else {
        EXPECT_GE(bounded, all - stats.largest_possible_shortfall - 1e-9);
        largest_reported = std::max(largest_reported, stats.largest_possible_shortfall);
      }
    }
  }
  std::cout << "small budget: " << proven << " searches proven by the relaxed bound, " << given_up
            << " given up (largest possible shortfall reported " << largest_reported << ")\n";
  EXPECT_GT(proven, 0);
  EXPECT_GT(given_up, 0);
}

}  // namespace
}  // namespace asr_ism_tree
