#include "asr_state_machine/world_model.hpp"

#include <gtest/gtest.h>

#include <random>

#include "asr_common/input_error.hpp"

namespace asr_state_machine {
namespace {

Pose at(double x, double y, double z) {
  return Pose(Eigen::Vector3d(x, y, z), Eigen::Quaterniond::Identity());
}

WorldModel breakfastModel() {
  WorldModel model;
  model.setSceneObjects(
      {{"breakfast", {{"Cup", "0"}, {"Plate", "0"}, {"Knife", "1"}, {"Knife", "2"}}},
       {"drinks", {{"Cup", "0"}, {"Juice", "0"}}}});
  return model;
}

TEST(WorldModel, RepeatedEstimatesOfOneObjectMergeIntoTheirMeanPose) {
  WorldModel model = breakfastModel();
  const auto first = model.addEstimate({{"Cup", "0"}, at(1.0, 0.0, 0.7)}, 5.0, 0);
  const auto second = model.addEstimate({{"Cup", "0"}, at(1.02, 0.0, 0.7)}, 9.0, 1);
  EXPECT_TRUE(first.is_new);
  EXPECT_FALSE(second.is_new);
  ASSERT_EQ(model.foundObjects().size(), 1u);
  const FoundObject& cup = model.foundObjects()[0];
  EXPECT_NEAR(cup.pose.position.x(), 1.01, 1e-12);
  EXPECT_EQ(cup.estimates, 2);
  EXPECT_EQ(cup.found_at_s, 5.0);  // when it was first seen
  EXPECT_EQ(cup.view, 0);
}

TEST(WorldModel, ObjectsOfOneTypeStayApartByIdAndByDistance) {
  WorldModel model = breakfastModel();
  model.addEstimate({{"Knife", "1"}, at(1.0, 0.0, 0.7)}, 0, 0);
  model.addEstimate({{"Knife", "2"}, at(1.01, 0.0, 0.7)}, 0, 0);  // near, but another id
  EXPECT_EQ(model.foundObjects().size(), 2u);
  model.addEstimate({{"Fork", ""}, at(2.0, 0.0, 0.7)}, 0, 0);
  model.addEstimate({{"Fork", ""}, at(2.5, 0.0, 0.7)}, 0, 0);   // far: a second fork
  model.addEstimate({{"Fork", ""}, at(2.04, 0.0, 0.7)}, 0, 0);  // near the first
  EXPECT_EQ(model.foundObjects().size(), 4u);
  EXPECT_EQ(model.foundObjects()[2].estimates, 2);
}

TEST(WorldModel, MissingObjectsPerSceneShrinkAsObjectsAreFound) {
  WorldModel model = breakfastModel();
  EXPECT_EQ(model.missingObjects("breakfast").size(), 4u);
  EXPECT_EQ(model.missingObjects().size(), 5u);  // Cup:0 is in both scenes, counted once
  model.addEstimate({{"Cup", "0"}, at(1.0, 0.0, 0.7)}, 0, 0);
  EXPECT_EQ(model.missingObjects("breakfast").size(), 3u);
  EXPECT_EQ(model.missingObjects("drinks"), (std::vector<ObjectKey>{{"Juice", "0"}}));
  // An estimate without id stands for one knife, not both.
  model.addEstimate({{"Knife", ""}, at(1.3, 0.0, 0.7)}, 0, 0);
  const std::vector<ObjectKey> missing = model.missingObjects("breakfast");
  EXPECT_EQ(missing.size(), 2u);
  EXPECT_EQ(std::count_if(missing.begin(), missing.end(),
                          [](const ObjectKey& k) { return k.type == "Knife"; }),
            1);
  EXPECT_EQ(model.missingTypes(), (std::vector<std::string>{"Juice", "Knife", "Plate"}));
  EXPECT_THROW(model.missingObjects("lunch"), asr_common::InputError);
}

TEST(WorldModel, ClutterNeverMakesAnObjectMissingOrFound) {
  WorldModel model = breakfastModel();
  model.addEstimate({{"Teapot", "0"}, at(1.0, 0.0, 0.7)}, 0, 0);
  EXPECT_EQ(model.missingObjects().size(), 5u);
  EXPECT_EQ(model.configuration().size(), 1u);
}

TEST(WorldModel, VisitedViewsAndSceneConfidencesAreKept) {
  WorldModel model = breakfastModel();
  EXPECT_EQ(model.addView({at(0, 0, 1.2), {"Cup", "Plate"}, 3.0, {}}), 0);
  EXPECT_EQ(model.addView({at(1, 0, 1.2), {"Knife"}, 8.0, {}}), 1);
  EXPECT_EQ(model.visitedViews()[1].types, std::vector<std::string>{"Knife"});
  EXPECT_EQ(model.sceneConfidence("breakfast"), 0.0);
  model.setSceneConfidence("breakfast", 0.6);
  model.setSceneConfidence("breakfast", 0.9);
  EXPECT_EQ(model.sceneConfidence("breakfast"), 0.9);
  model.clear();
  EXPECT_TRUE(model.visitedViews().empty());
  EXPECT_EQ(model.missingObjects().size(), 5u);  // the scenes stay
}

TEST(WorldModel, NonFiniteEstimatesAreRefused) {
  WorldModel model = breakfastModel();
  EXPECT_THROW(model.addEstimate({{"Cup", "0"}, at(NAN, 0, 0)}, 0, 0), asr_common::InputError);
  EXPECT_TRUE(model.foundObjects().empty());
}

// Property: noisy repeated estimates of objects far apart always give one found object each,
// whatever the order they arrive in, and each pose stays within the noise of its truth.
TEST(WorldModel, NoisyEstimatesOfSeparateObjectsGiveOneFoundObjectEach) {
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (int trial = 0; trial < 50; ++trial) {
    WorldModel model;
    std::vector<Eigen::Vector3d> truth;
    for (int i = 0; i < 6; ++i)
      truth.emplace_back(0.5 * i, 0.3 * (i % 2), 0.7);
    std::vector<int> order;
    for (int r = 0; r < 5; ++r)
      for (int i = 0; i < 6; ++i)
        order.push_back(i);
    std::shuffle(order.begin(), order.end(), random);
    for (int i : order) {
      const Eigen::Vector3d p = truth[i] + Eigen::Vector3d(noise(random), noise(random), 0);
      model.addEstimate({{"Cup", ""}, at(p.x(), p.y(), p.z())}, 0, 0);
    }
    ASSERT_EQ(model.foundObjects().size(), 6u) << "trial " << trial;
    for (const FoundObject& found : model.foundObjects()) {
      double nearest = 1e9;
      for (const auto& t : truth)
        nearest = std::min(nearest, (t - found.pose.position).norm());
      EXPECT_LT(nearest, 0.03);
      EXPECT_EQ(found.estimates, 5);
    }
  }
}

}  // namespace
}  // namespace asr_state_machine
