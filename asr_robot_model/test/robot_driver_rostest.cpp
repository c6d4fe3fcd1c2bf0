// robot_driver end to end on simulated time (rostest, robot_sim.launch): a goal reaches its state
// after the motion model's seconds, and /clock advanced by exactly those; the tf frames put the
// camera where the forward kinematics says; goals with NaN, out-of-limit angles, a base in
// furniture or outside the room are refused with a clear result and the clock stands still.
#include <actionlib/client/simple_action_client.h>
#include <asr_msgs/MoveHeadAction.h>
#include <asr_msgs/MoveRobotAction.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_eigen/tf2_eigen.h>
#include <tf2_ros/transform_listener.h>

#include <cmath>
#include <type_traits>

#include "asr_common/testing/rostest_support.hpp"
#include "asr_robot_model/forward_kinematics.hpp"
#include "asr_robot_model/motion_model.hpp"
#include "simulation_probe.hpp"

namespace asr_robot_model {
namespace {

using asr_common::testing::waitFor;
using asr_msgs::MoveHeadAction;
using asr_msgs::MoveRobotAction;

class RobotDriverTest : public ::testing::Test {
 protected:
  void SetUp() override {
    joints_ = handle_.subscribe<sensor_msgs::JointState>(
        "joint_states", 10,
        [this](const sensor_msgs::JointStateConstPtr& m) { joints_seen_ = *m; });
    ASSERT_TRUE(waitFor(
        [&] { return move_robot_.isServerConnected() && move_head_.isServerConnected(); }, 60))
        << "robot_driver did not start";
    ASSERT_TRUE(probe_.waitForDriver(30));
  }

  // Sends the goal and waits for its result (counting the feedback messages).
  template <typename Client, typename Goal>
  auto move(Client& client, const Goal& goal, int* feedbacks = nullptr) {
    using Result = std::decay_t<decltype(*client.getResult())>;
    client.sendGoal(goal, typename Client::SimpleDoneCallback(),
                    typename Client::SimpleActiveCallback(),
                    typename Client::SimpleFeedbackCallback([feedbacks](const auto&) {
                      if (feedbacks)
                        ++*feedbacks;
                    }));
    EXPECT_TRUE(waitFor([&] { return client.getState().isDone(); }, 60));
    return client.getResult() ? Result(*client.getResult()) : Result();
  }

  void expectRefused(const asr_msgs::MoveRobotGoal& goal, std::uint8_t outcome,
                     const std::string& named) {
    const ros::Time before = probe_.clock();
    const auto result = move(move_robot_, goal);
    EXPECT_EQ(move_robot_.getState(), actionlib::SimpleClientGoalState::ABORTED);
    EXPECT_EQ(result.outcome, outcome) << result.message;
    EXPECT_NE(result.message.find(named), std::string::npos) << result.message;
    EXPECT_EQ(result.seconds, 0.0);
    EXPECT_EQ(probe_.clock(), before) << "a refused goal took time";
  }

  ros::NodeHandle handle_;
  testing::SimulationProbe probe_;
  testing::Kitchen kitchen_;
  actionlib::SimpleActionClient<MoveRobotAction> move_robot_{"move_robot", false};
  actionlib::SimpleActionClient<MoveHeadAction> move_head_{"move_head", false};
  ros::Subscriber joints_;
  sensor_msgs::JointState joints_seen_;
};

void expectState(const asr_msgs::RobotState& reached, const RobotState& expected) {
  EXPECT_DOUBLE_EQ(reached.x, expected.x);
  EXPECT_DOUBLE_EQ(reached.y, expected.y);
  EXPECT_DOUBLE_EQ(reached.yaw, expected.yaw);
  EXPECT_DOUBLE_EQ(reached.pan, expected.pan);
  EXPECT_DOUBLE_EQ(reached.tilt, expected.tilt);
}

TEST_F(RobotDriverTest, GoalIsReachedAfterTheMotionModelsSimulatedSeconds) {
  const RobotState from = probe_.state();
  const RobotState target{1.2, 1.0, 1.0, 0.3, -0.2};
  const double seconds = motionBetween(from, target, speedsOf(kitchen_.robot)).seconds;
  ASSERT_GT(seconds, 1.0);
  const ros::Time before = probe_.clock();
  asr_msgs::MoveRobotGoal goal;
  goal.target = ros_interface::toStateMessage(target);
  int feedbacks = 0;
  const auto result = move(move_robot_, goal, &feedbacks);
  EXPECT_EQ(move_robot_.getState(), actionlib::SimpleClientGoalState::SUCCEEDED);
  EXPECT_EQ(result.outcome, asr_msgs::MoveRobotResult::REACHED) << result.message;
  expectState(result.state, target);
  EXPECT_NEAR(result.seconds, seconds, 1e-9);
  EXPECT_GE(feedbacks, 1);
  // The simulation owns time: /clock moved by the motion's seconds, not by wall time.
  const ros::Time after = probe_.waitForClock(before + ros::Duration(seconds));
  EXPECT_NEAR((after - before).toSec(), seconds, 1e-6);
  ASSERT_TRUE(waitFor(
      [&] { return joints_seen_.position.size() == 2 && joints_seen_.position[0] == target.pan; },
      10));
  EXPECT_EQ(joints_seen_.name[0], "ptu_pan_joint");
  EXPECT_DOUBLE_EQ(joints_seen_.position[1], target.tilt);
  // The frames chain map -> base_footprint -> ... -> camera_optical_frame like the kinematics.
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  const asr_common::Pose camera = cameraPose(kitchen_.robot, target);
  Eigen::Isometry3d seen = Eigen::Isometry3d::Identity();
  EXPECT_TRUE(waitFor(
      [&] {
        try {
          seen = tf2::transformToEigen(buffer.lookupTransform("map", kCameraFrame, ros::Time(0)));
        } catch (const tf2::TransformException&) {
          return false;
        }
        return (seen.translation() - camera.position).norm() < 1e-6;
      },
      10));
  EXPECT_LT((seen.translation() - camera.position).norm(), 1e-6);
  EXPECT_LT(Eigen::Quaterniond(seen.linear()).angularDistance(camera.orientation), 1e-6);
}

TEST_F(RobotDriverTest, HeadMovesAloneAtItsJointSpeeds) {
  const RobotState from = probe_.state();
  asr_msgs::MoveHeadGoal goal;
  goal.pan = from.pan - 0.5;
  goal.tilt = 0.1;
  const double seconds = std::max(0.5 / kitchen_.robot.pan.velocity,
                                  std::abs(0.1 - from.tilt) / kitchen_.robot.tilt.velocity);
  const ros::Time before = probe_.clock();
  const auto result = move(move_head_, goal);
  EXPECT_EQ(result.outcome, asr_msgs::MoveHeadResult::REACHED) << result.message;
  RobotState expected = from;
  expected.pan = goal.pan;
  expected.tilt = goal.tilt;
  expectState(result.state, expected);
  EXPECT_NEAR(result.seconds, seconds, 1e-9);
  EXPECT_NEAR((probe_.waitForClock(before + ros::Duration(seconds)) - before).toSec(), seconds,
              1e-6);
}

TEST_F(RobotDriverTest, NonFiniteGoalsAreRefusedNamingTheField) {
  asr_msgs::MoveRobotGoal goal;
  goal.target = ros_interface::toStateMessage({NAN, 1.0, 0, 0, 0});
  expectRefused(goal, asr_msgs::MoveRobotResult::INVALID, "x = nan");
  asr_msgs::MoveHeadGoal head;
  head.pan = 0.0;
  head.tilt = INFINITY;
  const auto result = move(move_head_, head);
  EXPECT_EQ(result.outcome, asr_msgs::MoveHeadResult::INVALID);
  EXPECT_NE(result.message.find("tilt = inf"), std::string::npos) << result.message;
}

TEST_F(RobotDriverTest, AnglesOutsideTheJointLimitsAreRefused) {
  asr_msgs::MoveRobotGoal goal;
  goal.target = ros_interface::toStateMessage({1.2, 1.0, 0, 1.5, 0});
  expectRefused(goal, asr_msgs::MoveRobotResult::JOINT_LIMIT, "ptu_pan_joint");
  asr_msgs::MoveHeadGoal head;
  head.pan = 0.0;
  head.tilt = -1.0;
  const auto result = move(move_head_, head);
  EXPECT_EQ(result.outcome, asr_msgs::MoveHeadResult::JOINT_LIMIT);
  EXPECT_NE(result.message.find("ptu_tilt_joint"), std::string::npos) << result.message;
}

TEST_F(RobotDriverTest, BaseInFurnitureOrOutsideTheRoomIsRefused) {
  asr_msgs::MoveRobotGoal goal;
  goal.target = ros_interface::toStateMessage({3.0, 2.5, 0, 0, 0});  // under the table
  expectRefused(goal, asr_msgs::MoveRobotResult::BASE_COLLISION, "furniture 'table'");
  goal.target = ros_interface::toStateMessage({5.7, 1.2, 0, 0, 0});  // in the cupboard
  expectRefused(goal, asr_msgs::MoveRobotResult::BASE_COLLISION, "furniture 'cupboard'");
  goal.target = ros_interface::toStateMessage({-1.0, 2.0, 0, 0, 0});
  expectRefused(goal, asr_msgs::MoveRobotResult::OUTSIDE_ROOM, "leave the room");
}

}  // namespace
}  // namespace asr_robot_model

int main(int argc, char** argv) {
  return asr_common::testing::runRostests(argc, argv, "robot_driver_rostest");
}
