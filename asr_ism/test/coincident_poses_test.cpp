#include "asr_ism/coincident_poses.hpp"

#include <gtest/gtest.h>

#include <random>

namespace asr_ism {
namespace {

using asr_common::Pose;

Pose at(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation) {
  return Pose(position, orientation.normalized());
}

TEST(CoincidentPoses, APoseWithinRoundingIsPresentWhereverItLies) {
  // Random poses, some next to a cell border (1e-6 m cells), each looked up shifted by up to
  // 0.9e-9 m (present), by 3e-9 m (absent), and with the quaternion's sign flipped (present).
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(-300.0, 300.0), unit(-1.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    Eigen::Vector3d position(coordinate(random), coordinate(random), coordinate(random));
    if (trial % 2 == 0)
      position.x() = std::round(position.x() * 1e6) * 1e-6 + unit(random) * 1e-9;
    const Eigen::Quaterniond orientation(unit(random), unit(random), unit(random), unit(random));
    CoincidentPoses poses;
    poses.insert(at(position, orientation));
    const Eigen::Vector3d direction =
        Eigen::Vector3d(unit(random), unit(random), unit(random)).normalized();
    EXPECT_TRUE(poses.contains(at(position + 0.9e-9 * direction, orientation)));
    EXPECT_FALSE(poses.contains(at(position + 3e-9 * direction, orientation)));
    EXPECT_TRUE(poses.contains(at(position, Eigen::Quaterniond(-orientation.coeffs()))));
  }
}

TEST(CoincidentPoses, ADifferentOrientationIsNew) {
  CoincidentPoses poses;
  const Pose pose(Eigen::Vector3d(1.0, 2.0, 3.0), Eigen::Quaterniond::Identity());
  EXPECT_TRUE(poses.insertIfNew(pose));
  EXPECT_FALSE(poses.insertIfNew(pose));
  const Pose turned(pose.position,
                    Eigen::Quaterniond(Eigen::AngleAxisd(1e-4, Eigen::Vector3d::UnitZ())));
  EXPECT_TRUE(poses.insertIfNew(turned));
}

}  // namespace
}  // namespace asr_ism
