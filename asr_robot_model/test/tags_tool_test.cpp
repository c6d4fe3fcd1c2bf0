// `asr tags render|detect|print` run as a user runs them: the kitchen rendered and its objects
// found at their true poses, printed sheets that the detector reads back, bad input named.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "asr_common/testing/tool_run.hpp"
#include "asr_robot_model/camera_intrinsics.hpp"
#include "asr_robot_model/shipped_files.hpp"
#include "asr_robot_model/testing/tag_scene.hpp"
#include "asr_robot_model/world.hpp"

using asr_common::testing::runTool;
using asr_common::testing::TempDir;
using nlohmann::json;

namespace {

std::string kitchen() {
  return asr_robot_model::shippedFile("config/worlds/kitchen.yaml");
}

std::string poseText(const asr_common::Pose& pose) {
  std::ostringstream text;
  text.precision(17);
  text << pose.position.x() << " " << pose.position.y() << " " << pose.position.z() << " "
       << pose.orientation.x() << " " << pose.orientation.y() << " " << pose.orientation.z() << " "
       << pose.orientation.w();
  return text.str();
}

asr_common::Pose poseOf(const json& pose) {
  auto number = [&](const char* part, const char* axis) { return pose[part][axis].get<double>(); };
  return asr_common::Pose(
      Eigen::Vector3d(number("position", "x"), number("position", "y"), number("position", "z")),
      Eigen::Quaterniond(number("orientation", "w"), number("orientation", "x"),
                         number("orientation", "y"), number("orientation", "z")));
}

}  // namespace

TEST(TagsTool, RendersTheKitchenAndFindsTheCupWhereItStands) {
  TempDir dir("tags_tool");
  const auto world = asr_robot_model::loadWorld(
      kitchen(), asr_robot_model::loadObjectCatalogue(asr_robot_model::defaultObjectCatalogue()));
  const auto cup = std::find_if(world.objects.begin(), world.objects.end(),
                                [](const auto& o) { return o.key.type == "Cup"; });
  ASSERT_NE(cup, world.objects.end());
  // 80 cm in front of the cup's -x face, a little above it.
  const asr_common::Pose camera = asr_robot_model::testing::lookAt(
      cup->box.pose.position + Eigen::Vector3d(-0.8, 0.05, 0.25), cup->box.pose.position);
  const auto render =
      runTool(TAGS_TOOL, dir,
              {"render", "--world", kitchen(), "--camera", poseText(camera), "--out",
               dir.file("view.png"), "--save-camera-info", dir.file("camera.yaml"), "--seed", "3"});
  asr_common::testing::expectSuccess(render);
  const auto detect = runTool(TAGS_TOOL, dir,
                              {"detect", "--image", dir.file("view.png"), "--camera-info",
                               dir.file("camera.yaml"), "--json"});
  asr_common::testing::expectSuccess(detect);
  const json result = json::parse(detect.out);
  bool found = false;
  for (const json& object : result["objects"])
    if (object["type"] == "Cup" && object["id"] == "0") {
      found = true;
      const asr_common::Pose truth = asr_common::relativePose(camera, cup->box.pose);
      const asr_common::Pose estimate = poseOf(object["pose"]);
      EXPECT_LE((estimate.position - truth.position).norm(), 0.02) << detect.out;
      EXPECT_LE(asr_common::angleBetween(estimate.orientation, truth.orientation), 0.07);
      EXPECT_EQ(object["covariance"].size(), 36u);
    }
  EXPECT_TRUE(found) << detect.out;
  ASSERT_FALSE(result["tags"].empty());
  EXPECT_TRUE(result["tags"][0].contains("reprojection_px"));
}

// The sheet's edges are perfectly sharp, which quad decimation aliases: read at full resolution,
// as a photograph of the printed sheet would be read at the default.
TEST(TagsTool, APrintedSheetIsReadBackByTheDetector) {
  TempDir dir("tags_tool");
  const auto print =
      runTool(TAGS_TOOL, dir,
              {"print", "--ids", "0-3,9", "--out", dir.file("sheet.png"), "--cell-px", "12"});
  asr_common::testing::expectSuccess(print);
  const cv::Mat sheet = cv::imread(dir.file("sheet.png"), cv::IMREAD_GRAYSCALE);
  ASSERT_FALSE(sheet.empty());
  asr_robot_model::saveCameraInfo(
      dir.file("camera.yaml"),
      asr_robot_model::CameraIntrinsics::fromHorizontalFov(sheet.cols, sheet.rows, 1.0));
  const auto detect = runTool(TAGS_TOOL, dir,
                              {"detect", "--image", dir.file("sheet.png"), "--camera-info",
                               dir.file("camera.yaml"), "--decimate", "1", "--json"});
  asr_common::testing::expectSuccess(detect);
  std::vector<int> ids;
  const json result = json::parse(detect.out);
  for (const json& tag : result["tags"])
    ids.push_back(tag["id"]);
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(ids, (std::vector<int>{0, 1, 2, 3, 9})) << detect.out;
}

TEST(TagsTool, BadInputIsNamed) {
  TempDir dir("tags_tool");
  // Exit code 1 and the last line of stderr naming `what`.
  auto expectNamed = [&](const std::vector<std::string>& arguments, const std::string& what) {
    const auto run = runTool(TAGS_TOOL, dir, arguments);
    EXPECT_EQ(run.exit_code, 1) << asr_common::testing::describe(run);
    ASSERT_FALSE(run.err.empty());
    EXPECT_NE(run.err.back().find(what), std::string::npos) << run.err.back();
  };
  expectNamed({"detect", "--image", dir.file("none.png"), "--camera-info", dir.file("camera.yaml")},
              "none.png");
  cv::imwrite(dir.file("grey.png"), cv::Mat(48, 64, CV_8U, cv::Scalar(128)));
  dir.write("camera.yaml", "image_width: 64\nimage_height: 48\ncamera_matrix: {data: [1]}\n");
  expectNamed({"detect", "--image", dir.file("grey.png"), "--camera-info", dir.file("camera.yaml")},
              "camera_matrix");
  expectNamed({"print", "--ids", "586-588", "--out", dir.file("x.png")}, "tag 587");
  const auto bad_ids = runTool(TAGS_TOOL, dir, {"print", "--ids", "5-2", "--out", "x.png"});
  EXPECT_EQ(bad_ids.exit_code, 2);
}
