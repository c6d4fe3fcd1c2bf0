// Forward and inverse kinematics: FK(IK(v)) = v over random reachable views of two robots, the
// cheapest solution, and refusals with the right reason.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "asr_robot_model/forward_kinematics.hpp"
#include "asr_robot_model/inverse_kinematics.hpp"

using namespace asr_robot_model;

namespace {

const char* const kOtherRobot = ASR_ROBOT_MODEL_TEST_DATA "/other_robot.urdf";

RobotState randomState(const RobotDescription& robot, std::mt19937& random) {
  std::uniform_real_distribution<double> coordinate(-5.0, 5.0);
  std::uniform_real_distribution<double> yaw(-M_PI, M_PI);
  std::uniform_real_distribution<double> pan(robot.pan.lower, robot.pan.upper);
  std::uniform_real_distribution<double> tilt(robot.tilt.lower, robot.tilt.upper);
  return {coordinate(random), coordinate(random), yaw(random), pan(random), tilt(random)};
}

Eigen::Vector3d viewingDirection(const asr_common::Pose& pose) {
  return pose.orientation * Eigen::Vector3d::UnitZ();
}

double angleOf(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// The requested pose turned about its own optical axis by `roll`.
Eigen::Quaterniond rolled(const asr_common::Pose& pose, double roll) {
  return pose.orientation * Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ());
}

class Kinematics : public ::testing::TestWithParam<std::string> {
 protected:
  RobotDescription robot_ = loadRobotDescription(GetParam());
  InverseKinematics ik_{robot_, speedsOf(robot_)};
};

}  // namespace

TEST(ForwardKinematics, ShippedRobotCameraFollowsTheBase) {
  const RobotDescription robot = loadRobotDescription(defaultRobotUrdf());
  const asr_common::Pose camera = cameraPose(robot, {1.0, 2.0, M_PI / 2, 0.0, 0.0});
  // The mast is 0.1 m ahead of the base centre; the base faces +y.
  EXPECT_TRUE(camera.position.isApprox(Eigen::Vector3d(1.0, 2.1, 1.4), 1e-12)) << camera.position;
  EXPECT_TRUE(viewingDirection(camera).isApprox(Eigen::Vector3d::UnitY(), 1e-12));
}

TEST_P(Kinematics, ForwardOfInverseReproducesTenThousandRandomReachableViews) {
  std::mt19937 random(14);
  std::uniform_real_distribution<double> roll(-M_PI, M_PI);
  for (int i = 0; i < 10000; ++i) {
    const RobotState truth = randomState(robot_, random);
    const asr_common::Pose view = cameraPose(robot_, truth);
    const double requested_roll = roll(random);
    const IkResult result =
        ik_.solve(view.position, rolled(view, requested_roll), randomState(robot_, random));
    ASSERT_TRUE(result.reachable) << i << ": " << result.explanation;
    EXPECT_TRUE(robot_.pan.withinLimits(result.state.pan)) << i;
    EXPECT_TRUE(robot_.tilt.withinLimits(result.state.tilt)) << i;
    const asr_common::Pose reached = cameraPose(robot_, result.state);
    ASSERT_LE((reached.position - view.position).norm(), 1e-6) << i;
    ASSERT_LE(angleOf(viewingDirection(reached), viewingDirection(view)), 1e-6) << i;
    // The head cannot roll: the reached roll is the head's, and the difference is reported.
    EXPECT_NEAR(result.roll_difference, std::abs(requested_roll), 1e-6) << i;
    EXPECT_TRUE(asr_common::approximatelyEqual(result.camera, reached, 1e-12, 1e-12)) << i;
  }
}

TEST_P(Kinematics, ChoosesTheSolutionCheapestToReachFromTheCurrentState) {
  std::mt19937 random(15);
  const MotionSpeeds speeds = speedsOf(robot_);
  for (int i = 0; i < 200; ++i) {
    const asr_common::Pose view = cameraPose(robot_, randomState(robot_, random));
    const RobotState from = randomState(robot_, random);
    const IkResult result = ik_.solve(view.position, view.orientation, from);
    ASSERT_TRUE(result.reachable) << result.explanation;
    EXPECT_NEAR(result.seconds, motionBetween(from, result.state, speeds).seconds, 1e-12);
    // Brute force: every pan on a fine grid, each completed to the state giving the view.
    double cheapest = result.seconds;
    for (int k = 0; k <= 1000; ++k) {
      const double pan = robot_.pan.lower + (robot_.pan.upper - robot_.pan.lower) * k / 1000.0;
      const IkResult only_this_pan = InverseKinematics(
                                         [&] {
                                           RobotDescription fixed = robot_;
                                           fixed.pan.lower = pan;
                                           fixed.pan.upper = pan;
                                           return fixed;
                                         }(),
                                         speeds)
                                         .solve(view.position, view.orientation, from);
      if (only_this_pan.reachable)
        cheapest = std::min(cheapest, only_this_pan.seconds);
    }
    EXPECT_LE(result.seconds, cheapest + 1e-3) << i;
  }
}

TEST_P(Kinematics, ViewAtAnotherHeightIsRefusedForHeight) {
  std::mt19937 random(16);
  std::uniform_real_distribution<double> offset(0.001, 1.0);
  std::bernoulli_distribution up;
  for (int i = 0; i < 1000; ++i) {
    asr_common::Pose view = cameraPose(robot_, randomState(robot_, random));
    view.position.z() += up(random) ? offset(random) : -offset(random);
    const IkResult result = ik_.solve(view.position, view.orientation, RobotState{});
    ASSERT_FALSE(result.reachable) << i;
    EXPECT_EQ(result.reason, Refusal::kHeight) << i << ": " << result.explanation;
    EXPECT_NE(result.explanation.find("height"), std::string::npos);
  }
}

TEST_P(Kinematics, InvalidPosesAreRefusedAsInvalid) {
  const asr_common::Pose view = cameraPose(robot_, RobotState{});
  const IkResult nan_position =
      ik_.solve(Eigen::Vector3d(NAN, 0, 1.4), view.orientation, RobotState{});
  EXPECT_EQ(nan_position.reason, Refusal::kInvalidPose);
  EXPECT_NE(nan_position.explanation.find("requested camera pose"), std::string::npos);
  const IkResult zero_quaternion =
      ik_.solve(view.position, Eigen::Quaterniond(0, 0, 0, 0), RobotState{});
  EXPECT_EQ(zero_quaternion.reason, Refusal::kInvalidPose);
  const IkResult long_quaternion =
      ik_.solve(view.position, Eigen::Quaterniond(2, 0, 0, 0), RobotState{});
  EXPECT_EQ(long_quaternion.reason, Refusal::kInvalidPose);
}

TEST_P(Kinematics, BaseCollisionIsRefusedAndAFreeBaseIsChosenWhenThereIsOne) {
  std::mt19937 random(17);
  const asr_common::Pose view = cameraPose(robot_, randomState(robot_, random));
  const IkResult blocked = ik_.solve(view.position, view.orientation, RobotState{},
                                     [](double, double, double) { return false; });
  EXPECT_EQ(blocked.reason, Refusal::kBaseCollision);
  // Only bases to the left of the viewing line are free (the cheapest solution may lie on the
  // right): the solution is exact and free.
  const Eigen::Vector3d direction = viewingDirection(view);
  const auto left_of_view = [&](double x, double y, double) {
    return direction.x() * (y - view.position.y()) - direction.y() * (x - view.position.x()) > 0;
  };
  for (const RobotState& from : {RobotState{}, RobotState{-3, 2, 1, 0.3, 0.1}}) {
    const IkResult free = ik_.solve(view.position, view.orientation, from, left_of_view);
    ASSERT_TRUE(free.reachable) << free.explanation;
    EXPECT_TRUE(left_of_view(free.state.x, free.state.y, free.state.yaw));
    EXPECT_LE((free.camera.position - view.position).norm(), 1e-6);
  }
}

INSTANTIATE_TEST_SUITE_P(Robots, Kinematics,
                         ::testing::Values(defaultRobotUrdf(), std::string(kOtherRobot)));

TEST(InverseKinematics, ShippedRobotRefusesElevationsBeyondTheTiltLimits) {
  const RobotDescription robot = loadRobotDescription(defaultRobotUrdf());
  const InverseKinematics ik(robot, speedsOf(robot));
  std::mt19937 random(18);
  std::uniform_real_distribution<double> steep_down(-89.0, -45.01), steep_up(25.01, 89.0);
  std::uniform_real_distribution<double> heading(-M_PI, M_PI);
  for (int i = 0; i < 1000; ++i) {
    const double elevation = (i % 2 == 0 ? steep_down(random) : steep_up(random)) * M_PI / 180;
    // The optical frame at yaw 0, pan 0 looks along +x; tilt it to `elevation`, turn it.
    const Eigen::Quaterniond level = cameraPose(robot, RobotState{}).orientation;
    const Eigen::Quaterniond orientation =
        Eigen::AngleAxisd(heading(random), Eigen::Vector3d::UnitZ()) *
        Eigen::AngleAxisd(-elevation, Eigen::Vector3d::UnitY()) * level;
    const IkResult result = ik.solve(Eigen::Vector3d(1, 1, 1.4), orientation, RobotState{});
    ASSERT_FALSE(result.reachable) << i;
    EXPECT_EQ(result.reason, Refusal::kTiltLimit) << i << ": " << result.explanation;
  }
}

TEST(InverseKinematics, RefusalsHaveStableNames) {
  EXPECT_STREQ(refusalName(Refusal::kTiltLimit), "tilt_limit");
  EXPECT_STREQ(refusalName(Refusal::kHeight), "height");
  EXPECT_STREQ(refusalName(Refusal::kBaseCollision), "base_collision");
  EXPECT_STREQ(refusalName(Refusal::kInvalidPose), "invalid_pose");
}
