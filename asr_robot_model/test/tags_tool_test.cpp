// `asr tags render|detect|print` run as a user runs them: the kitchen rendered and its objects
// found at their true poses, printed sheets that the detector reads back, bad input named.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
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

// Printed at 100 %, every tag's black square measures its tag map edge length (or --edge-mm for
// tags the map lacks): rasterised at 150 dpi (ghostscript) and read by a pinhole camera of focal
// length f pixels, each tag then lies at the same depth f * 25.4 mm / 150, whatever its size.
TEST(TagsTool, APrintedPdfHoldsEachTagAtItsTrueSize) {
  TempDir dir("tags_tool");
  const auto print =
      runTool(TAGS_TOOL, dir,
              {"print", "--ids", "0-4,9,100", "--edge-mm", "30", "--out", dir.file("tags.pdf")});
  asr_common::testing::expectSuccess(print);
  const std::string pdf = asr_common::testing::fileBytes(dir.file("tags.pdf"));
  EXPECT_EQ(pdf.rfind("%PDF-1.4\n", 0), 0u);
  EXPECT_NE(pdf.find("tag36h11 id 4, edge 120.0 mm"), std::string::npos);
  EXPECT_NE(pdf.find("tag36h11 id 100, edge 30.0 mm"), std::string::npos);
  // The cross-reference table points at each object.
  const std::size_t xref = std::stoul(pdf.substr(pdf.rfind("startxref") + 10));
  ASSERT_EQ(pdf.compare(xref, 5, "xref\n"), 0);
  std::istringstream table(pdf.substr(xref + 5));
  int first = 0, count = 0;
  table >> first >> count;
  for (int object = 0; object < count; ++object) {
    std::string offset, generation, use;
    table >> offset >> generation >> use;
    const std::string header = std::to_string(object) + " 0 obj";
    if (object > 0)
      EXPECT_EQ(pdf.substr(std::stoul(offset), header.size()), header);
  }

  const auto raster = asr_common::testing::runTool(
      "/usr/bin/gs", dir,
      {"-q", "-dNOPAUSE", "-dBATCH", "-dSAFER", "-sDEVICE=pnggray", "-r150",
       "-sOutputFile=" + dir.file("page%d.png"), dir.file("tags.pdf")});
  asr_common::testing::expectSuccess(raster);
  // Tags 0-3 (62.5 mm with their margins) two a row, the plate's tag 4 (150 mm) on page 2.
  std::vector<int> ids, unknown;
  for (const char* page_file : {"page1.png", "page2.png"}) {
    const cv::Mat page = cv::imread(dir.file(page_file), cv::IMREAD_GRAYSCALE);
    ASSERT_FALSE(page.empty()) << page_file;
    EXPECT_NEAR(page.cols, 210.0 / 25.4 * 150, 1.0);  // A4
    const auto camera =
        asr_robot_model::CameraIntrinsics::fromHorizontalFov(page.cols, page.rows, 1.0);
    asr_robot_model::saveCameraInfo(dir.file("camera.yaml"), camera);
    const auto detect = runTool(TAGS_TOOL, dir,
                                {"detect", "--image", dir.file(page_file), "--camera-info",
                                 dir.file("camera.yaml"), "--decimate", "1", "--json"});
    asr_common::testing::expectSuccess(detect);
    const json result = json::parse(detect.out);
    for (const json& tag : result["tags"]) {
      ids.push_back(tag["id"]);
      // Within 1 %: a pixel of the 150 dpi raster is 0.3 % of a 50 mm edge.
      const double depth = poseOf(tag["pose"]).position.z();
      EXPECT_NEAR(depth, camera.fx * 0.0254 / 150, 0.01 * depth) << tag["id"];
    }
    for (const json& id : result["unknown_ids"])
      unknown.push_back(id);
  }
  EXPECT_FALSE(std::filesystem::exists(dir.file("page3.png")));
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(ids, (std::vector<int>{0, 1, 2, 3, 4, 9}));
  EXPECT_EQ(unknown, std::vector<int>{100}) << "tag 100 is printed, not in the map";
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
  expectNamed({"print", "--ids", "100", "--edge-mm", "400", "--out", dir.file("x.pdf")}, "tag 100");
  const auto bad_ids = runTool(TAGS_TOOL, dir, {"print", "--ids", "5-2", "--out", "x.png"});
  EXPECT_EQ(bad_ids.exit_code, 2);
}
