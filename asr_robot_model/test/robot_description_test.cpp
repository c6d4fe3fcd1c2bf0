// The robot read from its URDF: the shipped robot's frames and limits, another robot, and
// malformed URDFs refused with the file and the field named.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_robot_model/forward_kinematics.hpp"
#include "asr_robot_model/robot_description.hpp"

using asr_common::testing::inputErrorOf;
using asr_common::testing::TempDir;
using namespace asr_robot_model;

namespace {

const double kDegree = M_PI / 180.0;

std::string shippedUrdfText() {
  return asr_common::testing::fileBytes(defaultRobotUrdf());
}

// The shipped URDF with `from` replaced by `to` (which must occur).
std::string shippedWith(const std::string& from, const std::string& to) {
  std::string text = shippedUrdfText();
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos)
    text.replace(at, from.size(), to);
  return text;
}

void expectRefused(const std::string& urdf, const std::string& field) {
  TempDir dir("robot_description");
  const std::string path = dir.write("broken.urdf", urdf);
  const std::string message = inputErrorOf([&] { loadRobotDescription(path); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find(field), std::string::npos) << "'" << field << "' in: " << message;
}

}  // namespace

TEST(RobotDescription, ShippedRobotHasTheIssuesLimitsAndACameraAt1Point4Metres) {
  const RobotDescription robot = loadRobotDescription(defaultRobotUrdf());
  EXPECT_NEAR(robot.pan.lower, -60 * kDegree, 1e-12);
  EXPECT_NEAR(robot.pan.upper, 60 * kDegree, 1e-12);
  EXPECT_NEAR(robot.tilt.lower, -45 * kDegree, 1e-12);
  EXPECT_NEAR(robot.tilt.upper, 25 * kDegree, 1e-12);
  EXPECT_DOUBLE_EQ(robot.pan.velocity, 1.0);
  EXPECT_DOUBLE_EQ(robot.tilt.velocity, 1.0);
  EXPECT_DOUBLE_EQ(robot.base_radius, 0.3);
  const Eigen::Isometry3d camera = cameraInBase(robot, 0.0, 0.0);
  EXPECT_NEAR(camera.translation().z(), 1.4, 1e-12);
}

TEST(RobotDescription, OpticalFrameLooksForwardWithXRightAndYDown) {
  const RobotDescription robot = loadRobotDescription(defaultRobotUrdf());
  const Eigen::Matrix3d axes = cameraInBase(robot, 0.0, 0.0).linear();
  EXPECT_TRUE(axes.col(2).isApprox(Eigen::Vector3d::UnitX(), 1e-12)) << axes;   // z forward
  EXPECT_TRUE(axes.col(0).isApprox(-Eigen::Vector3d::UnitY(), 1e-12)) << axes;  // x right
  EXPECT_TRUE(axes.col(1).isApprox(-Eigen::Vector3d::UnitZ(), 1e-12)) << axes;  // y down
}

TEST(RobotDescription, PositivePanTurnsLeftAndPositiveTiltLooksUp) {
  const RobotDescription robot = loadRobotDescription(defaultRobotUrdf());
  const Eigen::Vector3d panned = cameraInBase(robot, 0.5, 0.0).linear().col(2);
  EXPECT_GT(panned.y(), 0.4);
  const Eigen::Vector3d tilted = cameraInBase(robot, 0.0, 0.3).linear().col(2);
  EXPECT_NEAR(tilted.z(), std::sin(0.3), 1e-12);
}

TEST(RobotDescription, SecondRobotIsReadWithItsOwnOffsetsAndLimits) {
  const RobotDescription robot =
      loadRobotDescription(ASR_ROBOT_MODEL_TEST_DATA "/other_robot.urdf");
  EXPECT_DOUBLE_EQ(robot.pan.lower, -1.5);
  EXPECT_DOUBLE_EQ(robot.pan.upper, 1.4);
  EXPECT_DOUBLE_EQ(robot.tilt.velocity, 0.4);
  EXPECT_DOUBLE_EQ(robot.base_radius, 0.45);
  // base 0.05 + mast 0.9 + pan origin 0.08 - tilt origin 0.04 (the pan frame is upside down)
  // + camera 0.06 (the tilt frame is upright again).
  EXPECT_NEAR(cameraInBase(robot, 0.0, 0.0).translation().z(), 0.05 + 0.9 + 0.08 + 0.04 + 0.06,
              1e-12);
}

TEST(RobotDescription, MalformedUrdfsNameTheFileAndTheField) {
  expectRefused("<robot name=", "not a valid URDF");
  expectRefused(shippedWith("<link name=\"camera_optical_frame\"/>", ""), "camera_optical_frame");
  expectRefused(shippedWith("type=\"revolute\">\n    <parent link=\"ptu_pan_link\"/>",
                            "type=\"fixed\">\n    <parent link=\"ptu_pan_link\"/>"),
                "ptu_tilt_joint");
  expectRefused(shippedWith("name=\"ptu_pan_joint\" type=\"revolute\"",
                            "name=\"ptu_pan_joint\" type=\"continuous\""),
                "ptu_pan_joint");
  expectRefused(shippedWith("<axis xyz=\"0 0 1\"/>", "<axis xyz=\"1 0 0\"/>"),
                "ptu_pan_joint' axis");
  expectRefused(shippedWith("velocity=\"1.0\"", "velocity=\"0\""), "limit velocity");
  expectRefused(shippedWith("<geometry><cylinder radius=\"0.3\" length=\"0.3\"/></geometry>\n"
                            "    </collision>",
                            "<geometry><box size=\"1 1 1\"/></geometry>\n    </collision>"),
                "base_link' collision");
  expectRefused(shippedWith("lower=\"-0.7853981633974483\" upper=\"0.4363323129985824\"",
                            "lower=\"0.5\" upper=\"0.4\""),
                "ptu_tilt_joint' limit");
}

TEST(RobotDescription, MissingFileIsNamed) {
  const std::string message = inputErrorOf([] { loadRobotDescription("/no/such/robot.urdf"); });
  EXPECT_NE(message.find("/no/such/robot.urdf"), std::string::npos) << message;
}
