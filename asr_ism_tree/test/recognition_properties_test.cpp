// Invariants a robot acting on recognition relies on (issue 12, "Right answers"), checked over the
// kitchen recordings and office2016 with star, complete and optimised trees and seeded random
// turns, shifts and removals.

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <string>

#include "asr_common/input_error.hpp"
#include "asr_common/testing/recordings_skip.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism_tree/star_center.hpp"
#include "asr_ism_tree/topology_file.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"
#include "instance_lookup.hpp"
#include "random_perturbation.hpp"
#include "synthetic_scene.hpp"

namespace asr_ism_tree {
namespace {

using asr_common::Configuration;
using asr_common::Pose;
using asr_common::testing::recording;

constexpr double kDegree = M_PI / 180.0;
// How much lower than without it a badly seen object may leave the best instance of a tree: where
// the exact search completes and closes the pose gap (exact_best_search.hpp), rounding only.
// Where it gives up (beyond its votes or comparisons caps) or leaves the gap open (beyond its pose
// steps), subsets of the seen objects are recognised too (object_subsets.hpp), so the answer is
// at least that with the object removed unless their own cap cut them short (counted and
// printed; 15 of these 1,320 recognitions, where the property holds anyway). Rounding either
// way.
constexpr double kTolerance = 1e-9;

struct SceneFile {
  const char* file;
  const char* scene;
  // Relations selected by `select-topology` (docs/topology_table.csv), "" if none is stored.
  const char* optimised;
};

const SceneFile kScenes[] = {
    {"story_1.sqlite", "gedeck",
     "Cup marker_1\nCup marker_3\nPlateDeep marker_3\nPlateDeep marker_5\nPlateDeep marker_6\n"
     "marker_1 marker_5\nmarker_2 marker_4\nmarker_4 marker_5\nmarker_5 marker_6\n"},
    {"story_1.sqlite", "Gedeck_Ende",
     "Cup marker_4\nCup marker_6\nPlateDeep marker_6\nmarker_1 marker_2\nmarker_1 marker_5\n"
     "marker_2 marker_4\nmarker_2 marker_6\nmarker_3 marker_5\n"},
    {"story_1.sqlite", "Gedeck_Schrank_2", ""},
    {"story_1.sqlite", "Spuelkorb_3", ""},
    {"story_2.sqlite", "Brot_Gedeck_2", ""},
    {"story_2.sqlite", "Brot_Regal", ""},
    {"story_2.sqlite", "Getraenke_Gedeck", ""},
    {"story_2.sqlite", "Getraenke_Regal", ""},
    {"story_2.sqlite", "Muesli_Gedeck", ""},
    {"story_2.sqlite", "Muesli_Regal", ""},
    {"office2016.sqlite", "office2016", ""},
};

void PrintTo(const SceneFile& scene, std::ostream* out) {
  *out << scene.scene;
}

struct Learned {
  asr_ism::Demonstration demonstration;
  std::vector<std::pair<std::string, IsmTree>> trees;  // star, complete, optimised if stored
};

const Learned& learned(const SceneFile& scene) {
  static std::map<std::string, std::unique_ptr<Learned>> cache;
  std::unique_ptr<Learned>& entry = cache[scene.scene];
  if (!entry) {
    entry = std::make_unique<Learned>();
    entry->demonstration = asr_ism::sqlite::readDemonstration(recording(scene.file), scene.scene);
    const auto& objects = entry->demonstration.objects();
    const std::size_t center = chooseStarCenter(entry->demonstration);
    entry->trees.emplace_back(
        "star", generateIsmTree(entry->demonstration, RelationTopology::star(objects, center), {}));
    entry->trees.emplace_back(
        "complete", generateIsmTree(entry->demonstration, RelationTopology::complete(objects), {}));
    if (std::string(scene.optimised).size() > 0) {
      const asr_common::testing::TempDir folder("recognition_properties");
      const std::string path = folder.write("optimised.txt", scene.optimised);
      entry->trees.emplace_back(
          "optimised", generateIsmTree(entry->demonstration, readTopologyFile(path, objects), {}));
    }
  }
  return *entry;
}

class RecordedScene : public ::testing::TestWithParam<SceneFile> {
 protected:
  void SetUp() override { REQUIRE_RECORDINGS(); }
};

using test_support::oneObjectSeenBadly;
using test_support::perturbed;

// Seeing an object badly never scores lower than not seeing it: the instance without the object
// is still available when the object is seen, with the object adding a similarity >= 0.
TEST_P(RecordedScene, SeeingAnObjectBadlyNeverScoresLowerThanNotSeeingIt) {
  const Learned& scene = learned(GetParam());
  std::mt19937 random(12);
  double worst = 0.0, worst_given_up = 0.0;
  int given_up = 0, either_given_up = 0, proven = 0;
  double largest_possible = 0.0;
  std::size_t most_work = 0;  // comparisons of the exact search in one recognition
  // Of the pose-diverse evaluations: how many raised the best, how many ran out, their most work.
  std::size_t diverse_better = 0, diverse_given_up = 0, most_diverse_work = 0;
  // Of the recognitions of subsets of the seen objects: how many, how many raised the best, and
  // the recognitions where they ran out (only there is the property not guaranteed).
  std::size_t subset_searches = 0, subsets_better = 0, subsets_cut = 0, most_subsets = 0;
  // Recognitions whose search completed with the pose gap open (their best may fall short too).
  std::size_t gaps_open = 0;
  for (const auto& [topology, tree] : scene.trees) {
    const TreeRecognizer recognizer(tree);
    for (int trial = 0; trial < 40; ++trial) {
      const auto [changed, removed, what] = oneObjectSeenBadly(scene.demonstration, random);
      TreeRecognitionStats removed_stats, changed_stats;
      const double without = bestConfidence(recognizer.recognize(removed, &removed_stats));
      const double with = bestConfidence(recognizer.recognize(changed, &changed_stats));
      // Only where the search with the object gave up is its best not guaranteed.
      const bool exact = changed_stats.exact_searches_given_up == 0;
      (exact ? worst : worst_given_up) = std::max(exact ? worst : worst_given_up, without - with);
      given_up += exact ? 0 : 1;
      either_given_up +=
          changed_stats.exact_searches_given_up + removed_stats.exact_searches_given_up > 0 ? 1 : 0;
      proven += static_cast<int>(changed_stats.exact_searches_proven_by_bound +
                                 removed_stats.exact_searches_proven_by_bound);
      largest_possible = std::max(largest_possible, changed_stats.largest_possible_shortfall);
      most_work = std::max({most_work, removed_stats.exact_search_comparisons,
                            changed_stats.exact_search_comparisons});
      diverse_better +=
          changed_stats.diverse_evaluations_better + removed_stats.diverse_evaluations_better;
      diverse_given_up +=
          changed_stats.diverse_evaluations_given_up + removed_stats.diverse_evaluations_given_up;
      most_diverse_work = std::max({most_diverse_work, removed_stats.diverse_comparisons,
                                    changed_stats.diverse_comparisons});
      subset_searches += changed_stats.object_subset_searches;
      subsets_better += changed_stats.object_subsets_better;
      most_subsets = std::max(most_subsets, changed_stats.object_subset_searches);
      subsets_cut += changed_stats.object_subset_searches_cut;
      gaps_open += changed_stats.pose_gaps_left_open > 0 ? 1 : 0;
      EXPECT_GE(with, without - kTolerance) << topology << " tree, " << what;
    }
  }
  std::cout << GetParam().scene << ": largest shortfall " << worst
            << "; the exact search gave up in " << given_up << " cases with the object seen ("
            << either_given_up << " with or without it), largest shortfall there " << worst_given_up
            << "; at most " << most_work << " comparisons in the exact search of one recognition; "
            << proven
            << " searches proven by the relaxed bound, largest possible shortfall shown by it "
            << largest_possible << "; the pose-diverse evaluation raised the best in "
            << diverse_better << " recognitions and ran out in " << diverse_given_up
            << ", with at most " << most_diverse_work << " comparisons; " << subset_searches
            << " recognitions of subsets of the seen objects (at most " << most_subsets
            << " in one) raised the best in " << subsets_better << ", ran out in " << subsets_cut
            << "; the pose gap stayed open in " << gaps_open << "\n";
}

// A rigid motion: a shift of up to `max_shift` metres and a turn about the x, y or z axis or a
// random axis (one case in four each).
Pose randomRigidMotion(std::mt19937& random, double max_shift) {
  std::uniform_real_distribution<double> shift(-max_shift, max_shift), angle(-M_PI, M_PI);
  std::normal_distribution<double> normal(0.0, 1.0);
  const int kind = std::uniform_int_distribution<int>(0, 3)(random);
  const Eigen::Vector3d axis =
      kind < 3 ? Eigen::Vector3d::Unit(kind)
               : Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized();
  const Eigen::Vector3d offset(shift(random), shift(random), shift(random));
  return Pose(offset, Eigen::Quaterniond(Eigen::AngleAxisd(angle(random), axis)).normalized());
}

Configuration movedRigidly(Configuration configuration, const Pose& motion) {
  for (auto& estimate : configuration)
    estimate.pose = asr_common::compose(motion, estimate.pose);
  return configuration;
}

// The outcome of a recognition that must not depend on where the world frame lies.
struct WorkOutcome {
  double best = 0.0;
  TreeRecognitionStats stats;
};

WorkOutcome recognizeCounting(const TreeRecognizer& recognizer,
                              const Configuration& configuration) {
  WorkOutcome outcome;
  outcome.best = bestConfidence(recognizer.recognize(configuration, &outcome.stats));
  return outcome;
}

void expectSameWork(const WorkOutcome& expected, const WorkOutcome& got, const std::string& what) {
  EXPECT_NEAR(got.best, expected.best, 1e-9) << what;
  EXPECT_EQ(got.stats.exact_searches_given_up, expected.stats.exact_searches_given_up) << what;
  EXPECT_EQ(got.stats.pose_gaps_left_open, expected.stats.pose_gaps_left_open) << what;
  EXPECT_EQ(got.stats.exact_search_comparisons, expected.stats.exact_search_comparisons) << what;
  EXPECT_EQ(got.stats.exact_search_votes, expected.stats.exact_search_votes) << what;
  EXPECT_EQ(got.stats.diverse_evaluations, expected.stats.diverse_evaluations) << what;
  EXPECT_EQ(got.stats.diverse_comparisons, expected.stats.diverse_comparisons) << what;
  EXPECT_EQ(got.stats.object_subset_searches, expected.stats.object_subset_searches) << what;
  EXPECT_EQ(got.stats.object_subset_work, expected.stats.object_subset_work) << what;
  EXPECT_EQ(got.stats.isms.comparisons, expected.stats.isms.comparisons) << what;
  EXPECT_EQ(got.stats.isms.votes, expected.stats.isms.votes) << what;
  EXPECT_EQ(got.stats.isms.bins, expected.stats.isms.bins) << what;
  EXPECT_EQ(got.stats.isms.candidates, expected.stats.isms.candidates) << what;
  EXPECT_EQ(got.stats.isms.neighbourhood_votes, expected.stats.isms.neighbourhood_votes) << what;
  EXPECT_EQ(got.stats.root_results, expected.stats.root_results) << what;
  EXPECT_EQ(got.stats.merged_estimates, expected.stats.merged_estimates) << what;
  EXPECT_EQ(got.stats.repeat_searches_given_up, expected.stats.repeat_searches_given_up) << what;
  EXPECT_EQ(got.stats.pose_steps, expected.stats.pose_steps) << what;
  EXPECT_EQ(got.stats.exact_searches_proven_by_bound, expected.stats.exact_searches_proven_by_bound)
      << what;
  EXPECT_EQ(got.stats.relaxed_bound_work, expected.stats.relaxed_bound_work) << what;
  EXPECT_EQ(got.stats.diverse_evaluations_better, expected.stats.diverse_evaluations_better)
      << what;
  EXPECT_EQ(got.stats.diverse_evaluations_given_up, expected.stats.diverse_evaluations_given_up)
      << what;
  EXPECT_EQ(got.stats.object_subsets_better, expected.stats.object_subsets_better) << what;
  EXPECT_EQ(got.stats.object_subset_searches_cut, expected.stats.object_subset_searches_cut)
      << what;
}

// How often the caps of expectWorkIndependentOfTheWorldFrame() decided.
struct CapsDecided {
  int comparisons = 0;  // the exact search gave up, or its second pass ran out
  int pose_steps = 0;   // the pose gap was left open
};

// Whether the exact search gives up, and its work, do not depend on where the world frame lies
// (nor on the input order):
// each ISM bins its votes in a frame taken from its inputs (asr_ism/ism_recognizer.hpp). Recorded
// sets with one object seen badly, moved rigidly up to 300 m and turned about every axis; once
// with the default caps, once with a comparisons cap of half what the search took, so that
// the cap decides, and, where the pose gap was sought, once with half its steps.
CapsDecided expectWorkIndependentOfTheWorldFrame(const IsmTree& tree, const std::string& name,
                                                 const std::vector<Configuration>& sets,
                                                 std::mt19937& random) {
  const TreeRecognizer recognizer(tree);
  CapsDecided decided;
  for (std::size_t set = 0; set < sets.size(); ++set) {
    const WorkOutcome original = recognizeCounting(recognizer, sets[set]);
    TreeRecognitionParameters small_cap, few_pose_steps;
    small_cap.exact_search_max_comparisons = original.stats.exact_search_comparisons / 2;
    few_pose_steps.exact_search_max_pose_steps = original.stats.pose_steps / 2;
    const TreeRecognizer capped(tree, small_cap);
    const TreeRecognizer pose_capped(tree, few_pose_steps);
    const WorkOutcome capped_original = recognizeCounting(capped, sets[set]);
    const bool seeks_poses = original.stats.pose_steps > 1;
    const WorkOutcome pose_capped_original =
        seeks_poses ? recognizeCounting(pose_capped, sets[set]) : WorkOutcome{};
    // The cap decides where the search gives up, or where it completes but runs out in its
    // second pass (seeking the poses of the pose gap, exact_best_search.hpp).
    decided.comparisons +=
        capped_original.stats.exact_searches_given_up + capped_original.stats.pose_gaps_left_open >
                0
            ? 1
            : 0;
    decided.pose_steps += pose_capped_original.stats.pose_gaps_left_open > 0 ? 1 : 0;
    for (double max_shift : {1.0, 300.0}) {
      const Pose motion = randomRigidMotion(random, max_shift);
      // In another order too: neither may matter.
      Configuration moved = movedRigidly(sets[set], motion);
      std::mt19937 order(static_cast<unsigned>(set));  // apart, so the motions stay as drawn
      std::shuffle(moved.begin(), moved.end(), order);
      const std::string what = name + ", set " + std::to_string(set) + ", shift up to " +
                               std::to_string(max_shift) + " m";
      expectSameWork(original, recognizeCounting(recognizer, moved), what);
      expectSameWork(capped_original, recognizeCounting(capped, moved), what + ", small cap");
      if (seeks_poses) {
        expectSameWork(pose_capped_original, recognizeCounting(pose_capped, moved),
                       what + ", few pose steps");
      }
    }
  }
  return decided;
}

TEST_P(RecordedScene, WorkDoesNotDependOnWhereTheWorldFrameLies) {
  const Learned& scene = learned(GetParam());
  std::mt19937 random(21);
  int capped_given_up = 0, cases = 0;
  for (const auto& [topology, tree] : scene.trees) {
    std::vector<Configuration> sets;
    for (int trial = 0; trial < 3; ++trial) {
      const std::size_t step = std::uniform_int_distribution<std::size_t>(
          0, scene.demonstration.stepCount() - 1)(random);
      Configuration configuration = scene.demonstration.configuration(step);
      const std::size_t object =
          std::uniform_int_distribution<std::size_t>(0, configuration.size() - 1)(random);
      configuration[object].pose =
          perturbed(configuration[object].pose, random,
                    std::uniform_real_distribution<double>(0.05, 1.0)(random));
      sets.push_back(configuration);
    }
    capped_given_up +=
        expectWorkIndependentOfTheWorldFrame(
            tree, std::string(GetParam().scene) + " " + topology + " tree", sets, random)
            .comparisons;
    cases += static_cast<int>(sets.size());
  }
  std::cout << GetParam().scene << ": the small comparisons cap decided in " << capped_given_up
            << " of " << cases << " cases\n";
}

// The same without recordings: a synthetic table of six objects, every object seen badly with
// odds 1/2 or not at all with odds 1/6, star and complete trees, 50 sets. On its ring, objects
// lie exactly 1.5 bins apart, so votes derived from one estimate fall exactly on cell borders of
// a grid anchored at another (asr_ism/grid_cell.hpp): without the nudge there, these draws
// differed between frames in 14 of their checks (9-44 with other seeds).
TEST(SyntheticScene, WorkDoesNotDependOnWhereTheWorldFrameLies) {
  const std::vector<asr_common::ObjectKey> objects = {
      {"Plate", "1"}, {"Cup", "1"}, {"Knife", "1"}, {"Fork", "1"}, {"Spoon", "1"}, {"Napkin", "1"}};
  const asr_ism::Demonstration demonstration = synthetic::demonstration("table", objects, 6);
  std::mt19937 random(11);
  int capped_given_up = 0, cases = 0;
  for (const RelationTopology& topology :
       {RelationTopology::star(objects, 0), RelationTopology::complete(objects)}) {
    const IsmTree tree = generateIsmTree(demonstration, topology, {});
    std::vector<Configuration> sets;
    for (int trial = 0; trial < 25; ++trial) {
      const std::size_t step =
          std::uniform_int_distribution<std::size_t>(0, demonstration.stepCount() - 1)(random);
      Configuration configuration;
      for (asr_common::ObjectEstimate estimate : demonstration.configuration(step)) {
        const int what = std::uniform_int_distribution<int>(0, 5)(random);
        if (what == 0)
          continue;
        if (what <= 2)
          estimate.pose = perturbed(estimate.pose, random, 0.3);
        configuration.push_back(estimate);
      }
      sets.push_back(configuration);
    }
    capped_given_up +=
        expectWorkIndependentOfTheWorldFrame(tree, "synthetic", sets, random).comparisons;
    cases += static_cast<int>(sets.size());
  }
  std::cout << "synthetic: the small comparisons cap decided in " << capped_given_up << " of "
            << cases << " cases\n";
  EXPECT_GT(capped_given_up, 0);
}

// With repeated detections and estimates without an id, the order among several estimates of
// one object, how they are merged and what the pose gap costs do not depend on where the world
// frame lies either (docs/recognition.md). A synthetic table with two cups, star and complete
// trees; each object seen up to four times, jittered by up to 2 cm / 4 deg, a cup's estimates
// without their id with odds 1/3 (at most three such, so at most 8 labellings). Seven objects:
// on the ring of six, objects lie exactly 0.15 m (1.5 bins) apart along their axes, so votes
// derived from one estimate fall exactly on bin borders of a frame anchored at another such
// vote, where rounding decided before asr_ism/grid_cell.hpp (some comparisons differed).
TEST(SyntheticScene, WorkWithRepeatedDetectionsDoesNotDependOnWhereTheWorldFrameLies) {
  const std::vector<asr_common::ObjectKey> objects = {
      {"Plate", "1"}, {"Cup", "1"},    {"Cup", "2"},  {"Knife", "1"},
      {"Fork", "1"},  {"Napkin", "1"}, {"Spoon", "1"}};
  const asr_ism::Demonstration demonstration = synthetic::demonstration("table", objects, 6);
  std::mt19937 random(8);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  CapsDecided decided;
  int cases = 0;
  std::size_t merged = 0, labellings = 0;
  for (const RelationTopology& topology :
       {RelationTopology::star(objects, 0), RelationTopology::complete(objects)}) {
    const IsmTree tree = generateIsmTree(demonstration, topology, {});
    std::vector<Configuration> sets;
    for (int trial = 0; trial < 10; ++trial) {
      const std::size_t step =
          std::uniform_int_distribution<std::size_t>(0, demonstration.stepCount() - 1)(random);
      const double metres = std::uniform_real_distribution<double>(0.002, 0.02)(random);
      const double radians = std::uniform_real_distribution<double>(0.5, 4.0)(random) * kDegree;
      Configuration configuration;
      int without_id = 0;
      for (const asr_common::ObjectEstimate& recorded : demonstration.configuration(step)) {
        const int copies = std::uniform_int_distribution<int>(0, 4)(random);  // 0: not seen
        for (int copy = 0; copy < copies; ++copy) {
          asr_common::ObjectEstimate estimate =
              test_support::jitteredRepeat(recorded, metres, radians, gaussian, random);
          if (estimate.key.type == "Cup" && without_id < 3 &&
              std::uniform_int_distribution<int>(0, 2)(random) == 0) {
            estimate.key.id = "";
            ++without_id;
          }
          configuration.push_back(estimate);
        }
      }
      labellings += std::size_t{1} << without_id;
      sets.push_back(configuration);
    }
    for (const Configuration& set : sets) {
      TreeRecognitionStats stats;
      TreeRecognizer(tree).recognize(set, &stats);
      merged += stats.merged_estimates;
    }
    const CapsDecided here = expectWorkIndependentOfTheWorldFrame(
        tree, std::string("repeats, ") + (topology.relationCount() == 6 ? "star" : "complete"),
        sets, random);
    decided.comparisons += here.comparisons;
    decided.pose_steps += here.pose_steps;
    cases += static_cast<int>(sets.size());
  }
  std::cout << "repeats: " << merged << " estimates merged, " << labellings
            << " labellings; the small comparisons cap decided in " << decided.comparisons << " of "
            << cases << " cases, half the pose steps in " << decided.pose_steps << "\n";
  EXPECT_GT(merged, 0u);
  EXPECT_GT(labellings, static_cast<std::size_t>(cases));
  EXPECT_GT(decided.comparisons, 0);
  EXPECT_GT(decided.pose_steps, 0);
}

// The example: in office2016 (complete tree), a marker turned about 30 deg scored 0.57
// where the configuration without it scored 0.71, and turned by 60 deg 0.71 again. Every
// recorded set, every object turned about its own z axis by 30 and 60 deg.
TEST(Office2016, TurnedObjectNeverScoresLowerThanMissingObject) {
  REQUIRE_RECORDINGS();
  const Learned& scene = learned(kScenes[10]);
  for (const auto& [topology, tree] : scene.trees) {
    const TreeRecognizer recognizer(tree);
    for (std::size_t step = 0; step < scene.demonstration.stepCount(); ++step) {
      const Configuration recorded = scene.demonstration.configuration(step);
      for (std::size_t object = 0; object < recorded.size(); ++object) {
        Configuration removed = recorded;
        removed.erase(removed.begin() + object);
        const double without = bestConfidence(recognizer.recognize(removed));
        for (double degrees : {30.0, 60.0}) {
          Configuration turned = recorded;
          turned[object].pose.orientation *=
              Eigen::Quaterniond(Eigen::AngleAxisd(degrees * kDegree, Eigen::Vector3d::UnitZ()));
          EXPECT_GE(bestConfidence(recognizer.recognize(turned)), without - 1e-9)
              << topology << " tree, set " << step << ", " << recorded[object].key.toString()
              << " turned by " << degrees << " deg";
        }
      }
    }
  }
}

// The scene's objects in place count alike in every topology: 7 of 8 give 0.875, 6 of 8 0.75.
// Where a missing object was the reference of a sub-ISM, that ISM's reference pose comes from the
// others' votes, a little off, and the placeholder's compliance in the parent scales the
// similarities below it: over these cases by at most 0.065.
TEST(Gedeck, ObjectConfidenceIsTheShareOfObjectsInPlaceInEveryTopology) {
  REQUIRE_RECORDINGS();
  const Learned& scene = learned(kScenes[0]);
  const Configuration recorded = scene.demonstration.configuration(5);
  for (const auto& [topology, tree] : scene.trees) {
    const TreeRecognizer recognizer(tree);
    const auto full = recognizer.recognize(recorded);
    ASSERT_FALSE(full.empty());
    EXPECT_NEAR(full[0].object_confidence, 1.0, 0.01) << topology;
    for (std::size_t left_out = 0; left_out < recorded.size(); ++left_out) {
      Configuration one_missing = recorded;
      one_missing.erase(one_missing.begin() + left_out);
      const auto instances = recognizer.recognize(one_missing);
      ASSERT_FALSE(instances.empty());
      std::cout << topology << " without " << recorded[left_out].key.type << ": confidence "
                << instances[0].confidence << ", object confidence "
                << instances[0].object_confidence << "\n";
      EXPECT_NEAR(instances[0].object_confidence, 7.0 / 8.0, 0.07)
          << topology << " without " << recorded[left_out].key.toString();
      Configuration two_missing = one_missing;
      two_missing.erase(two_missing.begin() + (left_out % two_missing.size()));
      const auto fewer = recognizer.recognize(two_missing);
      ASSERT_FALSE(fewer.empty());
      EXPECT_NEAR(fewer[0].object_confidence, 6.0 / 8.0, 0.07) << topology;
    }
  }
}

Configuration withIds(Configuration configuration, const std::string& id) {
  for (auto& estimate : configuration)
    estimate.key.id = id;
  return configuration;
}

// Most detectors report types only: estimates without an id, or with an id the model does not
// know, stand for the objects of their type. Spuelkorb_3 has two PlateDeep objects: the two
// id-less plates must be told apart by the best assignment, one estimate per object.
TEST_P(RecordedScene, EstimatesWithoutKnownIdsMatchByType) {
  const Learned& scene = learned(GetParam());
  for (const auto& [topology, tree] : scene.trees) {
    const TreeRecognizer recognizer(tree);
    for (std::size_t step = 0; step < scene.demonstration.stepCount(); step += 9) {
      const Configuration recorded = scene.demonstration.configuration(step);
      const auto with_ids = recognizer.recognize(recorded);
      ASSERT_FALSE(with_ids.empty());
      EXPECT_FALSE(with_ids[0].ids_ignored);
      for (const std::string id : {"", "no-such-id"}) {
        const auto by_type = recognizer.recognize(withIds(recorded, id));
        const std::string what =
            topology + " tree, set " + std::to_string(step) + ", ids '" + id + "'";
        ASSERT_FALSE(by_type.empty()) << what;
        EXPECT_TRUE(by_type[0].ids_ignored) << what;
        EXPECT_NEAR(by_type[0].confidence, with_ids[0].confidence, 1e-9) << what;
        EXPECT_NEAR(by_type[0].object_confidence, with_ids[0].object_confidence, 1e-9) << what;
        EXPECT_TRUE(by_type[0].missing.empty()) << what;
        // One estimate per object.
        std::set<int> used;
        for (const InstanceObject& object : by_type[0].objects)
          EXPECT_TRUE(used.insert(object.estimate).second) << what << ": " << object.key.toString();
      }
    }
  }
}

// A detector that reports one object several times: the best instance is that of the
// exhaustive search over every repeat (repeated_detections_test.cpp has the synthetic cases),
// here on recorded sets with every object seen one to three times (1 cm / 2 deg jitter), in the
// scenes where the exhaustive search to compare with takes well under a second (in gedeck it
// took more than 100 s for one case).
void expectRepeatedDetectionsReachTheExhaustiveBest(const SceneFile& file) {
  const Learned& scene = learned(file);
  TreeRecognitionParameters exhaustive;
  exhaustive.merge_repeated_detections = false;
  exhaustive.pass_every_result = true;
  std::mt19937 random(31);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  TreeRecognitionParameters representatives_only;
  representatives_only.exact_over_repeats = false;
  int completed = 0, short_of_exhaustive = 0, raised = 0;
  for (const auto& [topology, tree] : scene.trees) {
    const TreeRecognizer recognizer(tree), brute(tree, exhaustive),
        merged_only(tree, representatives_only);
    for (int trial = 0; trial < 4; ++trial) {
      const std::size_t step = std::uniform_int_distribution<std::size_t>(
          0, scene.demonstration.stepCount() - 1)(random);
      Configuration configuration;
      for (const asr_common::ObjectEstimate& recorded : scene.demonstration.configuration(step)) {
        const int copies = std::uniform_int_distribution<int>(1, 3)(random);
        for (int copy = 0; copy < copies; ++copy) {
          asr_common::ObjectEstimate estimate = recorded;
          estimate.pose.position +=
              0.01 * Eigen::Vector3d(gaussian(random), gaussian(random), gaussian(random));
          const Eigen::Vector3d axis(gaussian(random), gaussian(random), gaussian(random));
          estimate.pose.orientation = (estimate.pose.orientation *
                                       Eigen::Quaterniond(Eigen::AngleAxisd(
                                           2.0 * kDegree * gaussian(random), axis.normalized())))
                                          .normalized();
          configuration.push_back(estimate);
        }
      }
      TreeRecognitionStats stats;
      const double merged = bestConfidence(recognizer.recognize(configuration, &stats));
      const double all = bestConfidence(brute.recognize(configuration));
      const double alone = bestConfidence(merged_only.recognize(configuration));
      raised += merged > alone + 1e-9 ? 1 : 0;
      const std::string what = topology + " tree, set " + std::to_string(step);
      EXPECT_LE(merged, all + 1e-9) << what;
      if (stats.exact_searches_given_up == 0 && stats.repeat_searches_given_up == 0) {
        ++completed;
        short_of_exhaustive += merged < all - 1e-9 ? 1 : 0;
        EXPECT_GE(merged, all - 0.005) << what;
      }
    }
  }
  std::cout << file.scene << ": the searches completed in " << completed << " of "
            << 4 * scene.trees.size() << " cases, " << short_of_exhaustive
            << " short of the exhaustive search; the search over the repeats raised the best in "
            << raised << "\n";
  EXPECT_GT(completed, 0);
}

TEST(RepeatedDetections, ReachTheExhaustiveBestOnRecordedSets) {
  REQUIRE_RECORDINGS();
  for (const SceneFile& file : kScenes) {
    const std::string name = file.scene;
    if (name == "Getraenke_Gedeck" || name == "Getraenke_Regal" || name == "Muesli_Gedeck")
      expectRepeatedDetectionsReachTheExhaustiveBest(file);
  }
}

TEST(TypeMatching, UnknownTypesStayClutterAndKnownIdsKeepObjectsApart) {
  REQUIRE_RECORDINGS();
  const Learned& scene = learned(kScenes[3]);  // Spuelkorb_3: two PlateDeep
  const TreeRecognizer recognizer(scene.trees[0].second);
  Configuration configuration = scene.demonstration.configuration(4);
  configuration.push_back({{"Toaster", ""}, configuration[0].pose});
  const auto instances = recognizer.recognize(configuration);
  ASSERT_FALSE(instances.empty());
  EXPECT_FALSE(instances[0].ids_ignored);
  EXPECT_NEAR(instances[0].confidence,
              bestConfidence(recognizer.recognize(scene.demonstration.configuration(4))), 1e-12);
  // Swapping the ids of the two plates swaps which estimate each object gets.
  std::vector<std::size_t> plates;
  for (std::size_t e = 0; e < configuration.size(); ++e) {
    if (configuration[e].key.type == "PlateDeep")
      plates.push_back(e);
  }
  ASSERT_EQ(plates.size(), 2u);
  Configuration swapped = configuration;
  std::swap(swapped[plates[0]].key.id, swapped[plates[1]].key.id);
  const auto swapped_instances = recognizer.recognize(swapped);
  ASSERT_FALSE(swapped_instances.empty());
  EXPECT_LT(swapped_instances[0].confidence, instances[0].confidence - 0.05);
}

TEST(TypeMatching, TooManyAssignmentsAreRefusedClearly) {
  REQUIRE_RECORDINGS();
  const Learned& scene = learned(kScenes[3]);
  TreeRecognitionParameters parameters;
  parameters.max_labellings = 8;
  const TreeRecognizer recognizer(scene.trees[0].second, parameters);
  Configuration configuration = withIds(scene.demonstration.configuration(4), "");
  for (int copy = 0; copy < 3; ++copy) {
    for (const auto& estimate : scene.demonstration.configuration(4)) {
      if (estimate.key.type == "PlateDeep")
        configuration.push_back({{"PlateDeep", ""}, estimate.pose});
    }
  }
  try {
    recognizer.recognize(configuration);
    ADD_FAILURE() << "no error";
  } catch (const asr_common::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("more than 8 ways"), std::string::npos)
        << error.what();
  }
  parameters.max_estimates = 5;
  try {
    TreeRecognizer(scene.trees[0].second, parameters).recognize(configuration);
    ADD_FAILURE() << "no error";
  } catch (const asr_common::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("more than the configured maximum of 5"),
              std::string::npos)
        << error.what();
  }
}

std::string sceneName(const ::testing::TestParamInfo<SceneFile>& info) {
  return info.param.scene;
}

INSTANTIATE_TEST_SUITE_P(Recordings, RecordedScene, ::testing::ValuesIn(kScenes), sceneName);

}  // namespace
}  // namespace asr_ism_tree
