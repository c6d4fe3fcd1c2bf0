// The driver's goal checks: each refusal with the field and value named, valid goals accepted.
#include <gtest/gtest.h>

#include <cmath>

#include "asr_robot_model/goal_check.hpp"

using namespace asr_robot_model;

namespace {

class GoalCheck : public ::testing::Test {
 protected:
  GoalCheck()
      : robot_(loadRobotDescription(defaultRobotUrdf())), map_(world(), 0.02, robot_.base_radius) {}

  static World world() {
    World world;
    world.room_min = {-1, -1};
    world.room_max = {5, 4};
    world.furniture.push_back(
        {"table",
         {asr_common::Pose({2.0, 1.0, 0.36}, Eigen::Quaterniond::Identity()), {1.2, 0.8, 0.72}}});
    return world;
  }

  GoalVerdict check(const RobotState& goal) { return checkStateGoal(robot_, world_, map_, goal); }

  RobotDescription robot_;
  World world_ = world();
  WorldMap map_;
};

void expectRefused(const GoalVerdict& verdict, GoalRefusal refusal, const std::string& named) {
  EXPECT_EQ(verdict.refusal, refusal) << verdict.message;
  EXPECT_NE(verdict.message.find(named), std::string::npos) << verdict.message;
}

}  // namespace

TEST_F(GoalCheck, AcceptsAFreeStateWithinTheLimits) {
  const GoalVerdict verdict = check({0.0, 2.0, 1.0, 0.5, -0.3});
  EXPECT_EQ(verdict.refusal, GoalRefusal::kNone) << verdict.message;
  EXPECT_TRUE(verdict.message.empty());
}

TEST_F(GoalCheck, RefusesNonFiniteValuesNamingTheField) {
  expectRefused(check({NAN, 2.0, 0, 0, 0}), GoalRefusal::kInvalid, "x = nan");
  expectRefused(check({0, 2.0, INFINITY, 0, 0}), GoalRefusal::kInvalid, "yaw = inf");
  expectRefused(check({0, 2.0, 0, 0, NAN}), GoalRefusal::kInvalid, "tilt");
  expectRefused(checkHeadGoal(robot_, NAN, 0), GoalRefusal::kInvalid, "pan");
}

TEST_F(GoalCheck, RefusesAnglesOutsideTheUrdfLimits) {
  expectRefused(check({0, 2.0, 0, 1.2, 0}), GoalRefusal::kJointLimit, "ptu_pan_joint");
  expectRefused(checkHeadGoal(robot_, 0, 0.5), GoalRefusal::kJointLimit, "tilt = 0.5");
  EXPECT_EQ(checkHeadGoal(robot_, robot_.pan.upper, robot_.tilt.lower).refusal, GoalRefusal::kNone);
}

TEST_F(GoalCheck, RefusesABaseOutsideTheRoomOrInFurniture) {
  expectRefused(check({-0.8, 2.0, 0, 0, 0}), GoalRefusal::kOutsideRoom, "leave the room");
  expectRefused(check({9.0, 2.0, 0, 0, 0}), GoalRefusal::kOutsideRoom, "(9, 2)");
  expectRefused(check({2.0, 1.0, 0, 0, 0}), GoalRefusal::kBaseCollision, "furniture 'table'");
  expectRefused(check({2.0, 0.45, 0, 0, 0}), GoalRefusal::kBaseCollision, "'table'");
}
