// The suite's own demo scene through the whole engine: learning ISM trees from the synthetic
// breakfast demonstration and recognising recorded, moved and disturbed settings.
#include <gtest/gtest.h>

#include <cmath>

#include "asr_ism/synthetic_demonstration.hpp"
#include "asr_ism_tree/star_center.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"

namespace asr_ism_tree {
namespace {

using asr_common::Configuration;
using asr_common::Pose;
using asr_ism::Demonstration;

IsmTree learn(const Demonstration& demonstration, const std::string& topology) {
  const RelationTopology relations =
      topology == "star"
          ? RelationTopology::star(demonstration.objects(), chooseStarCenter(demonstration))
          : RelationTopology::complete(demonstration.objects());
  return generateIsmTree(demonstration, relations, asr_ism::IsmRecognitionParameters{});
}

SceneInstance best(const TreeRecognizer& recognizer, const Configuration& configuration) {
  const auto instances = recognizer.recognize(configuration);
  return instances.empty() ? SceneInstance{} : instances.front();
}

// The setting turned by 20 degrees about the vertical through the plate and shifted on the table.
Configuration movedSetting(const Configuration& configuration) {
  const Eigen::Vector3d pivot = configuration.front().pose.position;  // PlateDeep comes first
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(20.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ()));
  return asr_ism::transformConfiguration(
      configuration, Pose(pivot + Eigen::Vector3d(-0.05, 0.2, 0.0) - turn * pivot, turn));
}

double similarityOf(const SceneInstance& instance, const std::string& type) {
  for (const InstanceObject& object : instance.objects) {
    if (object.key.type == type)
      return object.similarity;
  }
  return -1.0;
}

class BreakfastTree : public ::testing::TestWithParam<std::string> {};

TEST_P(BreakfastTree, RecognisesEveryRecordedStep) {
  const Demonstration demonstration = asr_ism::makeBreakfastDemonstration(1);
  const IsmTree tree = learn(demonstration, GetParam());
  const TreeRecognizer recognizer(tree);
  for (std::size_t step = 0; step < demonstration.stepCount(); ++step) {
    EXPECT_GE(best(recognizer, demonstration.configuration(step)).confidence, 0.99)
        << "step " << step;
  }
}

TEST_P(BreakfastTree, RecognisesTheSettingMovedAndObservedAfresh) {
  const Demonstration demonstration = asr_ism::makeBreakfastDemonstration(1);
  const IsmTree tree = learn(demonstration, GetParam());
  const TreeRecognizer recognizer(tree);
  const Configuration moved = asr_ism::addSensorNoise(movedSetting(demonstration.configuration(30)),
                                                      0.003, M_PI / 180.0, 2);
  EXPECT_GE(best(recognizer, moved).confidence, 0.95);
}

TEST_P(BreakfastTree, RejectsAMisplacedCupAndATurnedKnife) {
  const Demonstration demonstration = asr_ism::makeBreakfastDemonstration(1);
  const IsmTree tree = learn(demonstration, GetParam());
  const TreeRecognizer recognizer(tree);
  const Configuration moved = movedSetting(demonstration.configuration(30));
  // The plate's x axis is the setting's "right"; the cup goes 25 cm to the left.
  Eigen::Vector3d right = moved.front().pose.orientation * Eigen::Vector3d::UnitX();
  right.z() = 0.0;
  const Configuration disturbed = asr_ism::disturbConfiguration(
      asr_ism::disturbConfiguration(moved, {"Cup", "0"}, -0.25 * right.normalized()),
      {"Knife", "0"}, Eigen::Vector3d::Zero(),
      Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ())));
  const SceneInstance instance = best(recognizer, disturbed);
  EXPECT_LT(instance.confidence, 0.8);
  EXPECT_GT(instance.confidence, 0.5);  // the other four objects still fit
  EXPECT_EQ(similarityOf(instance, "Cup"), 0.0);
  EXPECT_EQ(similarityOf(instance, "Knife"), 0.0);
  EXPECT_GT(similarityOf(instance, "Fork"), 0.9);
}

INSTANTIATE_TEST_SUITE_P(Topologies, BreakfastTree, ::testing::Values("star", "complete"));

TEST(SyntheticTree, CompleteTreeRecognisesItsOwnSteps) {
  const Demonstration demonstration = asr_ism::makeSyntheticDemonstration(6, 100, 3);
  const IsmTree tree = learn(demonstration, "complete");
  const TreeRecognizer recognizer(tree);
  for (std::size_t step = 0; step < demonstration.stepCount(); step += 9) {
    EXPECT_GE(best(recognizer, demonstration.configuration(step)).confidence, 0.99)
        << "step " << step;
  }
}

}  // namespace
}  // namespace asr_ism_tree
