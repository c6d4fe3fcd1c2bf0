#include "asr_ism_tree/repeated_detections.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"
#include "synthetic_scene.hpp"

namespace asr_ism_tree {
namespace {

using asr_common::Configuration;
using asr_common::Pose;

constexpr double kDegree = M_PI / 180.0;
const RepeatedDetectionTolerance kTolerance{0.05, 10.0 * kDegree};

Pose turned(const Pose& pose, double angle, const Eigen::Vector3d& axis) {
  return Pose(pose.position,
              (pose.orientation * Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized())))
                  .normalized());
}

std::vector<int> allOf(const std::vector<Pose>& poses) {
  std::vector<int> estimates(poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i)
    estimates[i] = static_cast<int>(i);
  return estimates;
}

TEST(MergeRepeatedDetections, NoneOrOneEstimateStaysAsItIs) {
  EXPECT_TRUE(mergeRepeatedDetections({}, {}, kTolerance).empty());
  const std::vector<Pose> poses = {Pose()};
  EXPECT_EQ(mergeRepeatedDetections({0}, poses, kTolerance), std::vector<int>{0});
}

TEST(MergeRepeatedDetections, EstimatesFartherApartThanTheToleranceAreAllKept) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Pose> poses;
    while (poses.size() < 30) {
      const Pose candidate(Eigen::Vector3d(coordinate(random), coordinate(random), 0.0),
                           Eigen::Quaterniond::Identity());
      const bool far = std::all_of(poses.begin(), poses.end(), [&](const Pose& other) {
        return (other.position - candidate.position).norm() > kTolerance.distance;
      });
      if (far)
        poses.push_back(candidate);
    }
    EXPECT_EQ(mergeRepeatedDetections(allOf(poses), poses, kTolerance), allOf(poses));
  }
}

TEST(MergeRepeatedDetections, TurnedFartherThanTheToleranceIsAnotherDetection) {
  const Pose pose(Eigen::Vector3d(1.0, 2.0, 0.5), Eigen::Quaterniond::Identity());
  const std::vector<Pose> poses = {pose, turned(pose, 15.0 * kDegree, Eigen::Vector3d::UnitZ()),
                                   turned(pose, 5.0 * kDegree, Eigen::Vector3d::UnitX())};
  EXPECT_EQ(mergeRepeatedDetections({0, 1, 2}, poses, kTolerance), (std::vector<int>{0, 1}));
}

TEST(MergeRepeatedDetections, AGroupIsRepresentedByTheDetectionNearestItsMean) {
  // Five detections along x within 4 cm of the first: the middle one represents them.
  std::vector<Pose> poses;
  for (int i = 0; i < 5; ++i)
    poses.emplace_back(Eigen::Vector3d(0.01 * i, 0.0, 0.0), Eigen::Quaterniond::Identity());
  EXPECT_EQ(mergeRepeatedDetections(allOf(poses), poses, kTolerance), std::vector<int>{2});
}

TEST(MergeRepeatedDetections, GroupsStayApartAcrossGridCells) {
  // Two clusters 30 cm apart, each straddling a cell border of the tolerance grid.
  std::vector<Pose> poses;
  for (double x : {0.045, 0.05, 0.055, 0.345, 0.35, 0.355})
    poses.emplace_back(Eigen::Vector3d(x, 0.0, 0.0), Eigen::Quaterniond::Identity());
  EXPECT_EQ(mergeRepeatedDetections(allOf(poses), poses, kTolerance), (std::vector<int>{1, 4}));
}

// Recognition with repeated detections: a scene of five objects, each seen `copies` times with
// jitter (1 cm, 2 deg, seeded).
class RepeatedDetectionsInATree : public ::testing::Test {
 protected:
  RepeatedDetectionsInATree()
      : demonstration_(synthetic::demonstration("breakfast", kObjects, 6)),
        trees_{generateIsmTree(demonstration_, RelationTopology::star(kObjects, 0), {}),
               generateIsmTree(demonstration_, RelationTopology::complete(kObjects), {})} {}

  Configuration jittered(std::size_t copies, unsigned seed) const {
    std::mt19937 random(seed);
    std::normal_distribution<double> gaussian(0.0, 1.0);
    const Configuration recorded = demonstration_.configuration(2);
    Configuration configuration;
    for (std::size_t copy = 0; copy < copies; ++copy) {
      for (asr_common::ObjectEstimate estimate : recorded) {
        if (copy > 0) {
          estimate.pose.position +=
              0.01 * Eigen::Vector3d(gaussian(random), gaussian(random), gaussian(random));
          estimate.pose =
              turned(estimate.pose, 2.0 * kDegree * gaussian(random),
                     Eigen::Vector3d(gaussian(random), gaussian(random), gaussian(random)));
        }
        configuration.push_back(estimate);
      }
    }
    return configuration;
  }

  static TreeRecognitionParameters exhaustive() {
    TreeRecognitionParameters parameters;
    parameters.merge_repeated_detections = false;
    return parameters;
  }

  inline static const std::vector<asr_common::ObjectKey> kObjects = {
      {"Plate", "1"}, {"Cup", "1"}, {"Knife", "1"}, {"Fork", "1"}, {"Spoon", "1"}};
  asr_ism::Demonstration demonstration_;
  IsmTree trees_[2];
};

void expectSameInstances(const std::vector<SceneInstance>& a, const std::vector<SceneInstance>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].confidence, b[i].confidence);
    EXPECT_TRUE(asr_common::approximatelyEqual(a[i].pose, b[i].pose, 0.0, 0.0));
    ASSERT_EQ(a[i].objects.size(), b[i].objects.size());
    for (std::size_t o = 0; o < a[i].objects.size(); ++o) {
      EXPECT_EQ(a[i].objects[o].estimate, b[i].objects[o].estimate);
      EXPECT_EQ(a[i].objects[o].similarity, b[i].objects[o].similarity);
    }
  }
}

TEST_F(RepeatedDetectionsInATree, WithoutRepeatsTheResultsAreThoseOfTheExhaustiveSearch) {
  // Every recorded step, and two copies of one far apart: nothing to merge, same answer.
  for (const IsmTree& tree : trees_) {
    const TreeRecognizer merging(tree), brute(tree, exhaustive());
    for (std::size_t step = 0; step < demonstration_.stepCount(); ++step) {
      Configuration configuration = demonstration_.configuration(step);
      for (asr_common::ObjectEstimate estimate : demonstration_.configuration(step)) {
        estimate.pose.position += Eigen::Vector3d(3.0, 0.0, 0.0);
        configuration.push_back(estimate);
      }
      TreeRecognitionStats stats;
      expectSameInstances(merging.recognize(configuration, &stats), brute.recognize(configuration));
      EXPECT_EQ(stats.merged_estimates, 0u);
    }
  }
}

TEST_F(RepeatedDetectionsInATree, RepeatsFindTheSceneAsWellAsTheirRepresentativesAlone) {
  // On small random cases: merged, the best instance is the one recognised from the
  // representatives alone, and never better than the exhaustive search over every repeat (the
  // star tree, one ISM, is exact; a tree passes up a few results per sub-ISM).
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const Configuration configuration = jittered(3, seed);
    for (std::size_t t = 0; t < 2; ++t) {
      SCOPED_TRACE("seed " + std::to_string(seed) + (t == 0 ? ", star" : ", complete"));
      const TreeRecognizer merging(trees_[t]), brute(trees_[t], exhaustive());
      TreeRecognitionStats stats;
      const auto merged = merging.recognize(configuration, &stats);
      const auto all = brute.recognize(configuration);
      ASSERT_FALSE(merged.empty());
      ASSERT_FALSE(all.empty());
      EXPECT_EQ(stats.merged_estimates, 2 * kObjects.size());
      Configuration representatives;
      for (const InstanceObject& object : merged.front().objects)
        representatives.push_back(configuration[object.estimate]);
      const auto alone = brute.recognize(representatives);
      ASSERT_FALSE(alone.empty());
      EXPECT_NEAR(merged.front().confidence, alone.front().confidence, 1e-12);
      EXPECT_GT(merged.front().confidence, 0.5);
      if (t == 0) {
        EXPECT_LE(merged.front().confidence, all.front().confidence + 1e-12);
      }
      // The exhaustive search may pick the best-fitting repeat of every object (here the
      // unjittered copy, confidence 1); the consensus repeat of each costs at most 0.04 here.
      EXPECT_GT(merged.front().confidence, all.front().confidence - 0.05);
      EXPECT_TRUE(merged.front().missing.empty());
    }
  }
}

TEST_F(RepeatedDetectionsInATree, WorkDoesNotGrowWithRepeats) {
  // Linear in clutter, counted in votes: ten and fifty repeats of every object cost the ISMs no
  // more votes than one detection each.
  for (const IsmTree& tree : trees_) {
    const TreeRecognizer recognizer(tree);
    TreeRecognitionStats once, ten, fifty;
    recognizer.recognize(jittered(1, 3), &once);
    recognizer.recognize(jittered(10, 3), &ten);
    recognizer.recognize(jittered(50, 3), &fifty);
    EXPECT_EQ(ten.isms.votes, once.isms.votes);
    EXPECT_EQ(fifty.isms.votes, once.isms.votes);
    EXPECT_EQ(fifty.merged_estimates, 49 * kObjects.size());
  }
}

}  // namespace
}  // namespace asr_ism_tree
