// The OctoMap of a world: free space for the base and occlusion golden cases.
#include <gtest/gtest.h>

#include <random>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_robot_model/world_map.hpp"

using namespace asr_robot_model;

namespace {

Box box(const Eigen::Vector3d& centre, const Eigen::Vector3d& size) {
  return {asr_common::Pose(centre, Eigen::Quaterniond::Identity()), size};
}

// The table, a thin screen at x = 0.6 in front of a camera at (0, 0, 1) looking along +x.
World goldenWorld() {
  World world;
  world.room_min = {-1, -1};
  world.room_max = {5, 4};
  world.furniture.push_back({"table", box({2.0, 1.0, 0.36}, {1.2, 0.8, 0.72})});
  world.furniture.push_back({"screen", box({0.6, 0.0, 1.0}, {0.05, 0.2, 0.2})});
  world.objects.push_back({{"Cup", "0"}, box({1.8, 1.1, 0.77}, {0.08, 0.08, 0.10}), {}});
  return world;
}

}  // namespace

TEST(WorldMap, BaseIsFreeInTheRoomAwayFromFurniture) {
  const WorldMap map(goldenWorld(), 0.02, 0.3);
  EXPECT_TRUE(map.baseIsFree(0.0, 2.0));
  EXPECT_TRUE(map.baseIsFree(2.0, 1.0 - 0.4 - 0.35));   // 5 cm clear of the table's side
  EXPECT_FALSE(map.baseIsFree(2.0, 1.0 - 0.4 - 0.25));  // the base overlaps the table
  EXPECT_FALSE(map.baseIsFree(2.0, 1.0));               // under the table top
  EXPECT_FALSE(map.baseIsFree(-0.8, 2.0));              // the disc leaves the room
  EXPECT_TRUE(map.baseIsFree(-0.65, 2.0));
  EXPECT_FALSE(map.baseIsFree(NAN, 2.0));
}

TEST(WorldMap, FurnitureAboveTheRobotDoesNotBlockTheBase) {
  World world = goldenWorld();
  world.furniture.push_back({"shelf", box({0.0, 3.0, 2.3}, {1.0, 0.4, 0.02})});
  EXPECT_TRUE(WorldMap(world, 0.02, 0.3, 2.0).baseIsFree(0.0, 3.0));
  EXPECT_FALSE(WorldMap(world, 0.02, 0.3, 2.5).baseIsFree(0.0, 3.0));
}

TEST(WorldMap, BehindTheScreenIsOccludedAndBesideItIsSeen) {
  const WorldMap map(goldenWorld(), 0.02, 0.3);
  const Eigen::Vector3d eye(0.0, 0.0, 1.0);
  EXPECT_FALSE(map.lineOfSight(eye, box({1.2, 0.0, 1.0}, {0.08, 0.08, 0.08})));
  // Beside and above: the rays pass the screen 0.1 m from its edges.
  EXPECT_TRUE(map.lineOfSight(eye, box({1.2, 0.4, 1.0}, {0.08, 0.08, 0.08})));
  EXPECT_TRUE(map.lineOfSight(eye, box({1.2, -0.4, 1.0}, {0.08, 0.08, 0.08})));
  EXPECT_TRUE(map.lineOfSight(eye, box({1.2, 0.0, 1.4}, {0.08, 0.08, 0.08})));
  // Just behind the screen's edge is still hidden.
  EXPECT_FALSE(map.lineOfSight(eye, box({1.2, 0.15, 1.0}, {0.08, 0.08, 0.08})));
}

TEST(WorldMap, CupOnTheTableIsSeenFromAboveAndNotThroughTheTable) {
  const World world = goldenWorld();
  const WorldMap map(world, 0.02, 0.3);
  const Box& cup = world.objects[0].box;
  EXPECT_TRUE(map.lineOfSight({1.0, 1.1, 1.4}, cup));   // from above the table's edge
  EXPECT_FALSE(map.lineOfSight({3.0, 1.1, 0.5}, cup));  // through the table's side
}

TEST(WorldMap, ShortcutOfTheLineOfSightAgreesWithTheRayCast) {
  // Random segments in and around the golden world (many pass near the boxes, many not), at two
  // resolutions: neither the shortcut nor the grid of occupied voxels changes the answer.
  std::mt19937 random(11);
  std::uniform_real_distribution<double> x(-1.0, 5.0), y(-1.0, 4.0), z(0.0, 2.0);
  for (const double resolution : {0.02, 0.05}) {
    const WorldMap map(goldenWorld(), resolution, 0.3);
    int unblocked = 0;
    for (int i = 0; i < 4000; ++i) {
      const Eigen::Vector3d eye(x(random), y(random), z(random));
      const Box target = box({x(random), y(random), z(random)}, {0.1, 0.1, 0.1});
      const bool cast = map.lineOfSightByRayCast(eye, target);
      ASSERT_EQ(map.lineOfSight(eye, target), cast)
          << "eye " << eye.transpose() << " target " << target.pose.position.transpose();
      unblocked += cast ? 1 : 0;
    }
    EXPECT_GT(unblocked, 1000);  // both answers occur often
    EXPECT_LT(unblocked, 3900);
  }
}

TEST(WorldMap, BadResolutionIsRefused) {
  EXPECT_NE(asr_common::testing::inputErrorOf([] {
              WorldMap(goldenWorld(), 0.0, 0.3);
            }).find("resolution"),
            std::string::npos);
}
