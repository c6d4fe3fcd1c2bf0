// PosePredictor: what is predicted (only objects the instance lacks), how the poses move with the
// scene, determinism, splitting poses among instances, and bad input.

#include "asr_pose_prediction/pose_predictor.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_ism/synthetic_demonstration.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"

namespace asr_pose_prediction {
namespace {

using asr_common::Configuration;
using asr_common::testing::inputErrorOf;
using asr_ism_tree::RelationTopology;
using asr_ism_tree::TreeRecognizer;

constexpr std::size_t kObjects = 5;

// A synthetic scene of five objects, its tree from the complete topology, and the configuration
// of one demonstrated step.
struct SyntheticScene {
  asr_ism::Demonstration demonstration =
      asr_ism::makeSyntheticDemonstration(kObjects, 40, 7, "table");
  IsmTree tree = asr_ism_tree::generateIsmTree(
      demonstration, RelationTopology::complete(demonstration.objects()), {});

  Configuration step(std::size_t index) const { return demonstration.configuration(index); }
};

const SyntheticScene& scene() {
  static const SyntheticScene instance;
  return instance;
}

Configuration without(Configuration configuration, const std::set<std::string>& types) {
  configuration.erase(std::remove_if(configuration.begin(), configuration.end(),
                                     [&](const asr_common::ObjectEstimate& estimate) {
                                       return types.count(estimate.key.type) > 0;
                                     }),
                      configuration.end());
  return configuration;
}

std::vector<SceneInstance> recognize(const Configuration& configuration) {
  const TreeRecognizer recognizer(scene().tree);
  return recognizer.recognize(configuration);
}

std::set<std::string> predictedTypes(const std::vector<ObjectPrediction>& predictions) {
  std::set<std::string> types;
  for (const ObjectPrediction& prediction : predictions)
    types.insert(prediction.object.type);
  return types;
}

TEST(PosePredictor, PredictsExactlyTheObjectsTheInstanceLacks) {
  const PosePredictor predictor(scene().tree);
  const std::string first = scene().tree.objects()[0].type;
  const std::string last = scene().tree.objects()[kObjects - 1].type;
  const std::vector<SceneInstance> instances = recognize(without(scene().step(3), {first, last}));
  ASSERT_FALSE(instances.empty());

  PredictionOptions options;
  options.samples = 25;
  const std::vector<ObjectPrediction> predictions = predictor.predict(instances, options);
  EXPECT_EQ(predictedTypes(predictions), (std::set<std::string>{first, last}));
  for (const ObjectPrediction& prediction : predictions) {
    EXPECT_EQ(prediction.poses.size(), 25u);
    EXPECT_FALSE(prediction.path.empty());
    EXPECT_EQ(prediction.path.front(), "table");
    for (const Pose& pose : prediction.poses) {
      EXPECT_TRUE(pose.position.allFinite());
      EXPECT_NEAR(pose.orientation.norm(), 1.0, 1e-12);
    }
  }
}

TEST(PosePredictor, ACompleteInstanceHasNothingToPredict) {
  const PosePredictor predictor(scene().tree);
  const std::vector<SceneInstance> instances = recognize(scene().step(5));
  ASSERT_FALSE(instances.empty());
  ASSERT_GE(instances.front().confidence, 0.99);
  EXPECT_TRUE(predictor.predict(instances, {}).empty());
  EXPECT_TRUE(predictor.objectsToPredict(instances.front()).empty());
}

TEST(PosePredictor, PredictionsFromAMissingObjectsStepComeCloseToWhereItWas) {
  // The left-out object was demonstrated exactly where it is, so some sampled relation chain
  // reproduces its pose up to the recognition's own estimate of the scene's pose.
  const PosePredictor predictor(scene().tree);
  const Configuration full = scene().step(11);
  const asr_common::ObjectEstimate truth = full[2];
  const std::vector<SceneInstance> instances = recognize(without(full, {truth.key.type}));
  ASSERT_FALSE(instances.empty());
  PredictionOptions options;
  options.samples = 400;
  const std::vector<ObjectPrediction> predictions = predictor.predict(instances, options);
  ASSERT_EQ(predictions.size(), 1u);
  double nearest = INFINITY;
  for (const Pose& pose : predictions[0].poses)
    nearest = std::min(nearest, (pose.position - truth.pose.position).norm());
  EXPECT_LT(nearest, 0.02);
}

TEST(PosePredictor, PredictionsMoveWithARotatedAndShiftedScene) {
  const PosePredictor predictor(scene().tree);
  const std::string left_out = scene().tree.objects()[1].type;
  const Configuration original = without(scene().step(8), {left_out});
  // A quarter turn about the vertical and a shift across the room.
  const Pose motion(Eigen::Vector3d(2.5, -1.25, 0.3),
                    Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ())));
  Configuration moved = original;
  for (asr_common::ObjectEstimate& estimate : moved)
    estimate.pose = asr_common::compose(motion, estimate.pose);

  PredictionOptions options;
  options.samples = 50;
  options.seed = 42;
  const std::vector<ObjectPrediction> before = predictor.predict(recognize(original), options);
  const std::vector<ObjectPrediction> after = predictor.predict(recognize(moved), options);
  ASSERT_EQ(before.size(), 1u);
  ASSERT_EQ(after.size(), 1u);
  ASSERT_EQ(before[0].poses.size(), after[0].poses.size());
  for (std::size_t i = 0; i < before[0].poses.size(); ++i) {
    const Pose expected = asr_common::compose(motion, before[0].poses[i]);
    EXPECT_LT((after[0].poses[i].position - expected.position).norm(), 1e-9) << "pose " << i;
    EXPECT_LT(asr_common::angleBetween(after[0].poses[i].orientation, expected.orientation), 1e-9)
        << "pose " << i;
  }
}

TEST(PosePredictor, TheSameSeedGivesTheSamePosesAndAnotherSeedOthers) {
  const PosePredictor predictor(scene().tree);
  const std::vector<SceneInstance> instances =
      recognize(without(scene().step(20), {scene().tree.objects()[3].type}));
  PredictionOptions options;
  options.samples = 30;
  options.seed = 9;
  const auto first = predictor.predict(instances, options);
  const auto again = predictor.predict(instances, options);
  options.seed = 10;
  const auto other = predictor.predict(instances, options);
  ASSERT_EQ(first.size(), 1u);
  bool any_different = false;
  for (std::size_t i = 0; i < first[0].poses.size(); ++i) {
    EXPECT_EQ(first[0].poses[i].position, again[0].poses[i].position);
    EXPECT_EQ(first[0].poses[i].orientation.coeffs(), again[0].poses[i].orientation.coeffs());
    any_different |= first[0].poses[i].position != other[0].poses[i].position;
  }
  EXPECT_TRUE(any_different);
}

TEST(PosePredictor, PosesAreSplitAmongTheBestInstancesByConfidence) {
  const PosePredictor predictor(scene().tree);
  const std::string left_out = scene().tree.objects()[0].type;
  // Two copies of the scene, far apart, the second with a further object missing: two
  // instances of different confidence, both lacking `left_out`.
  Configuration configuration = without(scene().step(4), {left_out});
  const Pose far(Eigen::Vector3d(20.0, 0.0, 0.0), Eigen::Quaterniond::Identity());
  for (const asr_common::ObjectEstimate& estimate :
       without(scene().step(4), {left_out, scene().tree.objects()[2].type})) {
    asr_common::ObjectEstimate copy = estimate;  // the same object keys again
    copy.pose = asr_common::compose(far, estimate.pose);
    configuration.push_back(copy);
  }
  std::vector<SceneInstance> instances = recognize(configuration);
  ASSERT_GE(instances.size(), 2u);
  PredictionOptions options;
  options.samples = 100;
  options.instances = 2;
  options.object = scene().tree.objects()[0];
  const std::vector<ObjectPrediction> predictions = predictor.predict(instances, options);
  ASSERT_EQ(predictions.size(), 1u);
  const auto& counts = predictions[0].poses_per_instance;
  ASSERT_EQ(counts.size(), 2u);
  EXPECT_EQ(counts[0] + counts[1], 100u);
  EXPECT_GT(counts[0], counts[1]);
  const double share =
      instances[0].confidence / (instances[0].confidence + instances[1].confidence);
  EXPECT_NEAR(static_cast<double>(counts[0]), 100.0 * share, 1.0);
}

TEST(PosePredictor, BadInputIsNamed) {
  const PosePredictor predictor(scene().tree);
  EXPECT_NE(inputErrorOf([&] { predictor.predict({}, {}); }).find("no instance"),
            std::string::npos);

  const std::vector<SceneInstance> instances =
      recognize(without(scene().step(2), {scene().tree.objects()[4].type}));
  PredictionOptions options;
  options.samples = 0;
  EXPECT_NE(inputErrorOf([&] { predictor.predict(instances, options); }).find("at least 1"),
            std::string::npos);

  options = {};
  options.object = asr_common::ObjectKey{"Teapot", "0"};
  const std::string unknown = inputErrorOf([&] { predictor.predict(instances, options); });
  EXPECT_NE(unknown.find("Teapot"), std::string::npos) << unknown;

  options.object = scene().tree.objects()[0];  // present in the instance
  const std::string present = inputErrorOf([&] { predictor.predict(instances, options); });
  EXPECT_NE(present.find("nothing to predict"), std::string::npos) << present;

  std::vector<SceneInstance> foreign = instances;
  foreign[0].scene = "kitchen_shelf";
  const std::string other_scene = inputErrorOf([&] { predictor.predict(foreign, {}); });
  EXPECT_NE(other_scene.find("kitchen_shelf"), std::string::npos) << other_scene;
}

}  // namespace
}  // namespace asr_pose_prediction
