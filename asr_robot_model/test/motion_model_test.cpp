// The motion time model: turn, drive, turn for the base, the head at the same time.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_robot_model/motion_model.hpp"

using namespace asr_robot_model;

namespace {

// A state with every value uniform in [-range, range].
RobotState randomState(std::mt19937& random, double range) {
  std::uniform_real_distribution<double> value(-range, range);
  return {value(random), value(random), value(random), value(random), value(random)};
}

}  // namespace

TEST(MotionModel, DrivingStraightAheadTakesDistanceOverSpeed) {
  const Motion motion = motionBetween({0, 0, 0, 0, 0}, {1, 0, 0, 0, 0}, MotionSpeeds{});
  EXPECT_DOUBLE_EQ(motion.seconds, 2.0);
  EXPECT_DOUBLE_EQ(motion.path_length, 1.0);
  EXPECT_DOUBLE_EQ(motion.turning, 0.0);
}

TEST(MotionModel, SidewaysGoalTurnsDrivesAndTurnsBack) {
  const Motion motion = motionBetween({0, 0, 0, 0, 0}, {0, 1, 0, 0, 0}, MotionSpeeds{});
  EXPECT_DOUBLE_EQ(motion.turning, M_PI);
  EXPECT_DOUBLE_EQ(motion.seconds, M_PI / 0.8 + 1.0 / 0.5);
}

TEST(MotionModel, TurnsTheShortWayRound) {
  const Motion motion = motionBetween({0, 0, 3.1, 0, 0}, {0, 0, -3.1, 0, 0}, MotionSpeeds{});
  EXPECT_NEAR(motion.turning, 2 * M_PI - 6.2, 1e-12);
  EXPECT_DOUBLE_EQ(motion.path_length, 0.0);
}

TEST(MotionModel, HeadMovesWhileTheBaseMovesAndTheSlowerSetsTheTime) {
  MotionSpeeds speeds;
  speeds.pan_speed = 0.5;
  speeds.tilt_speed = 0.25;
  const Motion head_only = motionBetween({0, 0, 0, -1, 0}, {0, 0, 0, 1, 0.2}, speeds);
  EXPECT_DOUBLE_EQ(head_only.head_seconds, 4.0);  // pan 2 rad at 0.5 rad/s
  EXPECT_DOUBLE_EQ(head_only.seconds, 4.0);
  const Motion both = motionBetween({0, 0, 0, 0, 0}, {3, 0, 0, 0, 0.5}, speeds);
  EXPECT_DOUBLE_EQ(both.head_seconds, 2.0);  // tilt 0.5 rad at 0.25 rad/s
  EXPECT_DOUBLE_EQ(both.base_seconds, 6.0);
  EXPECT_DOUBLE_EQ(both.seconds, 6.0);
}

TEST(MotionModel, PropertiesOverRandomStates) {
  std::mt19937 random(3);
  const MotionSpeeds speeds;
  for (int i = 0; i < 10000; ++i) {
    const RobotState a = randomState(random, 4.0);
    const RobotState b = randomState(random, 4.0);
    const Motion motion = motionBetween(a, b, speeds);
    EXPECT_NEAR(motion.path_length, std::hypot(b.x - a.x, b.y - a.y), 1e-12);
    EXPECT_LE(motion.turning, 2 * M_PI + 1e-12);
    EXPECT_GE(motion.seconds, motion.path_length / speeds.base_speed);
    EXPECT_GE(motion.seconds, std::abs(b.pan - a.pan) / speeds.pan_speed);
    EXPECT_DOUBLE_EQ(motionBetween(a, a, speeds).seconds, 0.0);
  }
}

TEST(MotionModel, SpeedsComeFromTheUrdfAndBadSpeedsAreNamed) {
  RobotDescription robot;
  robot.pan.velocity = 0.6;
  robot.tilt.velocity = 0.4;
  const MotionSpeeds speeds = speedsOf(robot);
  EXPECT_DOUBLE_EQ(speeds.pan_speed, 0.6);
  EXPECT_DOUBLE_EQ(speeds.tilt_speed, 0.4);
  EXPECT_DOUBLE_EQ(speeds.base_speed, 0.5);
  EXPECT_DOUBLE_EQ(speeds.turn_speed, 0.8);
  MotionSpeeds bad;
  bad.turn_speed = 0.0;
  const std::string message = asr_common::testing::inputErrorOf([&] { checkSpeeds(bad); });
  EXPECT_NE(message.find("turn_speed"), std::string::npos) << message;
}

TEST(MotionModel, StateAlongTurnsThenDrivesThenTurns) {
  const MotionSpeeds speeds;  // turn 0.8 rad/s, drive 0.5 m/s
  const RobotState from{0, 0, 0, 0, 0};
  const RobotState to{0, 1, 0, 0.5, 0};
  const double quarter = (M_PI / 2) / 0.8;
  const RobotState turning = stateAlong(from, to, speeds, quarter / 2);
  EXPECT_NEAR(turning.yaw, M_PI / 4, 1e-12);
  EXPECT_DOUBLE_EQ(turning.x, 0.0);
  const RobotState driving = stateAlong(from, to, speeds, quarter + 1.0);
  EXPECT_NEAR(driving.y, 0.5, 1e-12);
  EXPECT_NEAR(driving.yaw, M_PI / 2, 1e-12);
  EXPECT_DOUBLE_EQ(driving.pan, 0.5);  // the head arrived after 0.5 s
  const RobotState back = stateAlong(from, to, speeds, quarter + 2.0 + quarter / 2);
  EXPECT_NEAR(back.y, 1.0, 1e-12);
  EXPECT_NEAR(back.yaw, M_PI / 4, 1e-12);
}

// Along any motion the robot starts at `from`, ends at `to` exactly at the motion's seconds and
// never moves faster than its speeds between two instants.
TEST(MotionModel, StateAlongIsContinuousWithinTheSpeedsOverRandomMotions) {
  std::mt19937 random(5);
  const MotionSpeeds speeds;
  for (int i = 0; i < 500; ++i) {
    const RobotState a = randomState(random, 3.0);
    const RobotState b = randomState(random, 3.0);
    const double seconds = motionBetween(a, b, speeds).seconds;
    const RobotState start = stateAlong(a, b, speeds, 0.0);
    EXPECT_NEAR(start.x, a.x, 1e-12);
    EXPECT_NEAR(wrapAngle(start.yaw - a.yaw), 0.0, 1e-12);
    const RobotState end = stateAlong(a, b, speeds, seconds);
    EXPECT_EQ(end.x, b.x);
    EXPECT_EQ(end.yaw, b.yaw);
    const double step = seconds / 50;
    RobotState previous = start;
    for (int k = 1; k <= 50; ++k) {
      const RobotState now = stateAlong(a, b, speeds, k * step);
      EXPECT_LE(std::hypot(now.x - previous.x, now.y - previous.y),
                speeds.base_speed * step + 1e-9);
      EXPECT_LE(std::abs(wrapAngle(now.yaw - previous.yaw)), speeds.turn_speed * step + 1e-9);
      EXPECT_LE(std::abs(now.pan - previous.pan), speeds.pan_speed * step + 1e-9);
      EXPECT_LE(std::abs(now.tilt - previous.tilt), speeds.tilt_speed * step + 1e-9);
      previous = now;
    }
  }
}
