// The robot's frames for tf, from the URDF: chained from base_footprint to camera_optical_frame
// they give the forward kinematics' camera pose, for the shipped and the second robot.
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "asr_robot_model/forward_kinematics.hpp"
#include "asr_robot_model/robot_frames.hpp"

using namespace asr_robot_model;

namespace {

// The pose of `frame` in base_footprint, by walking up the parents.
Eigen::Isometry3d inBase(const std::vector<FrameTransform>& frames, std::string frame) {
  std::map<std::string, FrameTransform> by_child;
  for (const FrameTransform& entry : frames)
    by_child[entry.child] = entry;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  while (frame != kBaseFrame) {
    const FrameTransform& entry = by_child.at(frame);
    pose = entry.transform * pose;
    frame = entry.parent;
  }
  return pose;
}

void expectChainMatchesKinematics(const RobotDescription& robot) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> pan(robot.pan.lower, robot.pan.upper);
  std::uniform_real_distribution<double> tilt(robot.tilt.lower, robot.tilt.upper);
  std::vector<FrameTransform> fixed = fixedFrames(robot);
  for (int i = 0; i < 200; ++i) {
    const double p = pan(random), t = tilt(random);
    std::vector<FrameTransform> all = fixed;
    const auto moving = movingFrames(robot, p, t);
    all.insert(all.end(), moving.begin(), moving.end());
    EXPECT_EQ(all.size(), robot.joints.size());
    const Eigen::Isometry3d chained = inBase(all, kCameraFrame);
    const Eigen::Isometry3d expected = cameraInBase(robot, p, t);
    EXPECT_LT((chained.translation() - expected.translation()).norm(), 1e-12);
    EXPECT_LT((chained.linear() - expected.linear()).norm(), 1e-12);
  }
}

}  // namespace

TEST(RobotFrames, ChainOfTheShippedRobotIsItsForwardKinematics) {
  const RobotDescription robot = loadRobotDescription(defaultRobotUrdf());
  EXPECT_EQ(movingFrames(robot, 0, 0).size(), 2u);
  expectChainMatchesKinematics(robot);
}

TEST(RobotFrames, ChainOfTheSecondRobotIsItsForwardKinematics) {
  expectChainMatchesKinematics(loadRobotDescription(ASR_ROBOT_MODEL_TEST_DATA "/other_robot.urdf"));
}
