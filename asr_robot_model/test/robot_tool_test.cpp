// `asr robot fk|ik|detect` run as a user runs them: JSON out, errors on one line.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "asr_common/testing/tool_run.hpp"
#include "asr_robot_model/forward_kinematics.hpp"

using asr_common::testing::runTool;
using asr_common::testing::TempDir;
using nlohmann::json;

namespace {

const std::string kWorld = ASR_ROBOT_MODEL_TEST_DATA "/issue_example_world.yaml";

std::string poseText(const json& pose) {
  std::ostringstream text;
  text.precision(17);
  for (const char* k : {"x", "y", "z"})
    text << pose["position"][k].get<double>() << " ";
  for (const char* k : {"x", "y", "z", "w"})
    text << pose["orientation"][k].get<double>() << " ";
  return text.str();
}

}  // namespace

TEST(RobotTool, ForwardThenInverseComesBackToTheSameCamera) {
  TempDir dir("robot_tool");
  const auto fk = runTool(ROBOT_TOOL, dir, {"fk", "--state", "0.5 0.2 0.3 0.4 -0.2", "--json"});
  asr_common::testing::expectSuccess(fk);
  const json camera = json::parse(fk.out)["camera"];
  const auto robot = asr_robot_model::loadRobotDescription(asr_robot_model::defaultRobotUrdf());
  const asr_common::Pose expected = asr_robot_model::cameraPose(robot, {0.5, 0.2, 0.3, 0.4, -0.2});
  EXPECT_NEAR(camera["position"]["x"].get<double>(), expected.position.x(), 1e-12);
  const auto ik =
      runTool(ROBOT_TOOL, dir, {"ik", "--world", kWorld, "--camera", poseText(camera), "--json"});
  asr_common::testing::expectSuccess(ik);
  const json result = json::parse(ik.out);
  ASSERT_TRUE(result["reachable"].get<bool>()) << ik.out;
  EXPECT_NEAR(result["camera"]["position"]["y"].get<double>(), expected.position.y(), 1e-6);
  EXPECT_GT(result["seconds"].get<double>(), 0.0);
}

TEST(RobotTool, UnreachableViewSaysWhy) {
  TempDir dir("robot_tool");
  const auto ik = runTool(ROBOT_TOOL, dir, {"ik", "--camera", "1 1 0.3 0 0 0 1", "--json"});
  asr_common::testing::expectSuccess(ik);
  const json result = json::parse(ik.out);
  EXPECT_FALSE(result["reachable"].get<bool>());
  EXPECT_FALSE(result["reason"].get<std::string>().empty());
}

TEST(RobotTool, DetectsTheCupOfTheIssuesWorldFromItsSeenSideButNotFromAbove) {
  TempDir dir("robot_tool");
  // Straight above the cup no normal ([1, 0, 0], [0, 1, 0]) faces the camera.
  const auto above = runTool(ROBOT_TOOL, dir,
                             {"detect", "--world", kWorld, "--camera", "1.8 1.1 1.37 1 0 0 0",
                              "--types", "Cup", "--json"});
  asr_common::testing::expectSuccess(above);
  EXPECT_EQ(json::parse(above.out)["rejected"][0]["why"], "normals") << above.out;
  // From +x and above, looking down at the cup across the table.
  const Eigen::Vector3d eye(2.5, 1.1, 1.12), cup(1.8, 1.1, 0.77);
  const Eigen::Quaterniond look =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), cup - eye);
  std::ostringstream camera;
  camera.precision(17);
  camera << eye.x() << " " << eye.y() << " " << eye.z() << " " << look.x() << " " << look.y() << " "
         << look.z() << " " << look.w();
  const auto detect =
      runTool(ROBOT_TOOL, dir,
              {"detect", "--world", kWorld, "--camera", camera.str(), "--types", "Cup", "--json"});
  asr_common::testing::expectSuccess(detect);
  const json result = json::parse(detect.out);
  ASSERT_EQ(result["detected"].size(), 1u) << detect.out;
  EXPECT_EQ(result["detected"][0]["id"], "0");
  EXPECT_DOUBLE_EQ(result["seconds"].get<double>(), 3.0);
}

TEST(RobotTool, MalformedWorldIsOneLineNamingFileAndField) {
  TempDir dir("robot_tool");
  const std::string world = dir.write("w.yaml", "version: 1\nframe: map\nroom: {min: [0, 0]}\n");
  const auto run =
      runTool(ROBOT_TOOL, dir, {"detect", "--world", world, "--camera", "0 0 1 0 0 0 1"});
  EXPECT_EQ(run.exit_code, 1);
  ASSERT_EQ(run.err.size(), 1u) << asr_common::testing::describe(run);
  EXPECT_NE(run.err[0].find(world + ": room.max"), std::string::npos) << run.err[0];
  const auto usage = runTool(ROBOT_TOOL, dir, {"fk", "--state", "1 2 nan 0 0"});
  EXPECT_EQ(usage.exit_code, 2);
}
