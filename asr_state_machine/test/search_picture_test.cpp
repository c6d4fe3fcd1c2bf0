// The top-down picture of a search, and the search result's JSON it is drawn from.
#include "asr_state_machine/search_picture.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <random>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_state_machine/search_json.hpp"

namespace asr_state_machine {
namespace {

using asr_common::testing::inputErrorOf;
using asr_common::testing::TempDir;
using asr_robot_model::World;

Pose at(double x, double y, double z, double yaw = 0.0) {
  return Pose(Eigen::Vector3d(x, y, z),
              Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ())));
}

// A 5 x 4 m room with a table and a breakfast of two objects plus one of clutter.
World smallWorld() {
  World world;
  world.room_min = {0.0, 0.0};
  world.room_max = {5.0, 4.0};
  world.furniture.push_back({"table", {at(2.5, 2.0, 0.35), {1.2, 0.8, 0.7}}});
  world.objects.push_back({{"Cup", "0"}, {at(2.3, 2.1, 0.75), {0.08, 0.08, 0.1}}, {}});
  world.objects.push_back({{"Plate", "0"}, {at(2.7, 1.9, 0.72), {0.2, 0.2, 0.03}}, {}});
  world.objects.push_back({{"Box", "7"}, {at(2.9, 2.3, 0.75), {0.1, 0.1, 0.1}}, {}});
  return world;
}

// A camera on a robot at base (x, y, yaw), looking along the yaw and 30 degrees down.
Pose cameraAt(double x, double y, double yaw) {
  const Eigen::Quaterniond looking =
      Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
      Eigen::AngleAxisd(M_PI / 6, Eigen::Vector3d::UnitY()) *
      // optical frame: z forward, x right, y down
      Eigen::Quaterniond(
          Eigen::Matrix3d((Eigen::Matrix3d() << 0, 0, 1, -1, 0, 0, 0, -1, 0).finished()));
  return Pose(Eigen::Vector3d(x, y, 1.3), looking.normalized());
}

// A search that went from `start` through `bases` and found the cup from its second view.
SearchResult searchThrough(const RobotState& start, const std::vector<RobotState>& bases) {
  SearchResult result;
  result.outcome = Outcome::kNowhereLeftToSearch;
  result.reason = "no direct-search view is left";
  result.start = start;
  result.world.setSceneObjects({{"breakfast", {{"Cup", "0"}, {"Plate", "0"}}}});
  double t = 0.0;
  for (const RobotState& base : bases) {
    t += 10.0;
    result.world.addView({cameraAt(base.x, base.y, base.yaw), {"Cup", "Plate"}, t, base});
  }
  if (bases.size() > 1)
    result.world.addEstimate({{"Cup", "0"}, at(2.31, 2.1, 0.75)}, 23.0, 1);
  result.world.setSceneConfidence("breakfast", 0.5);
  result.sim_seconds = t + 6.0;
  result.log.push_back({0.0, "INIT", "start", "mode asr, 2 objects to find", 0.0});
  return result;
}

RobotState base(double x, double y, double yaw = 0.0) {
  return {x, y, yaw, 0.0, 0.0};
}

bool nearColour(const cv::Vec3b& bgr, const Rgb& rgb, int tolerance) {
  return std::abs(bgr[2] - rgb[0]) <= tolerance && std::abs(bgr[1] - rgb[1]) <= tolerance &&
         std::abs(bgr[0] - rgb[2]) <= tolerance;
}

// True if the path's colour is within a pixel of `where`.
bool pathAt(const cv::Mat& image, const Eigen::Vector2i& where) {
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      if (nearColour(image.at<cv::Vec3b>(where.y() + dy, where.x() + dx), kPathColour, 30))
        return true;
    }
  }
  return false;
}

TEST(SearchPicture, IsWrittenAtTheFramesSizeWithTheRoomOnTheLeft) {
  TempDir dir("search_picture");
  const World world = smallWorld();
  const std::string png = dir.file("search.png");
  writeSearchPicture(world, searchThrough(base(0.5, 0.5), {base(1.5, 1.0), base(2.0, 1.2)}), png);
  const cv::Mat image = cv::imread(png, cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  const TopDownFrame frame(world);
  EXPECT_EQ(image.cols, frame.width());
  EXPECT_EQ(image.rows, frame.height());
  EXPECT_EQ(frame.mapWidth(), 5 * 120 + 2 * TopDownFrame::kMargin);
  // North is up: the room's north-west corner is at the top left margin.
  EXPECT_EQ(frame.pixel({0.0, 4.0}), Eigen::Vector2i(TopDownFrame::kMargin, TopDownFrame::kMargin));
  EXPECT_EQ(frame.pixel({5.0, 0.0}),
            Eigen::Vector2i(TopDownFrame::kMargin + 600, TopDownFrame::kMargin + 480));
  // Bare floor far from the path, the furniture and the views stays the floor's colour.
  const Eigen::Vector2i floor = frame.pixel({4.6, 0.4});
  EXPECT_TRUE(nearColour(image.at<cv::Vec3b>(floor.y(), floor.x()), kFloorColour, 0));
  // The path is nowhere near that corner.
  EXPECT_FALSE(pathAt(image, floor));
}

TEST(SearchPicture, ThePathIsDrawnWhereTheRobotDrove) {
  // Property: over random searches, points along every leg of the path show the path's colour
  // (objects and labels drawn on top may hide a few).
  std::mt19937 random(7);
  std::uniform_real_distribution<double> x(0.3, 4.7), y(0.3, 3.7), yaw(-M_PI, M_PI);
  TempDir dir("search_picture_path");
  const World world = smallWorld();
  const TopDownFrame frame(world);
  for (int trial = 0; trial < 12; ++trial) {
    const RobotState start = base(x(random), y(random), yaw(random));
    std::vector<RobotState> bases;
    for (int i = 0; i < 2 + trial % 5; ++i)
      bases.push_back(base(x(random), y(random), yaw(random)));
    const std::string png = dir.file("path" + std::to_string(trial) + ".png");
    writeSearchPicture(world, searchThrough(start, bases), png);
    const cv::Mat image = cv::imread(png, cv::IMREAD_COLOR);
    ASSERT_FALSE(image.empty());
    int samples = 0, on_path = 0;
    RobotState from = start;
    for (const RobotState& to : bases) {
      for (double share : {0.3, 0.5, 0.7}) {
        const Eigen::Vector2d point =
            Eigen::Vector2d(from.x, from.y) + share * Eigen::Vector2d(to.x - from.x, to.y - from.y);
        ++samples;
        on_path += pathAt(image, frame.pixel(point));
      }
      from = to;
    }
    EXPECT_GE(on_path, samples * 8 / 10) << "trial " << trial;
  }
}

TEST(SearchPicture, ABadFileIsRefusedNamingIt) {
  TempDir dir("search_picture_bad");
  const World world = smallWorld();
  const SearchResult result = searchThrough(base(0.5, 0.5), {base(1.0, 1.0)});
  const std::string missing_folder = dir.file("no/such/folder/search.png");
  EXPECT_NE(
      inputErrorOf([&] { writeSearchPicture(world, result, missing_folder); }).find(missing_folder),
      std::string::npos);
  EXPECT_NE(inputErrorOf([&] { checkPictureFile(dir.path()); }).find(dir.path()),
            std::string::npos);
  EXPECT_NE(inputErrorOf([&] { checkPictureFile(""); }).find("file name"), std::string::npos);
  // An existing picture is replaced whole.
  const std::string png = dir.file("search.png");
  writeSearchPicture(world, result, png);
  writeSearchPicture(world, result, png);
  EXPECT_FALSE(cv::imread(png).empty());
}

TEST(SearchResultJson, ReadsBackWhatItWrote) {
  const SearchResult result =
      searchThrough(base(0.5, 0.5, 0.3), {base(1.5, 1.0, 1.0), base(2.0, 1.2, -2.0)});
  const nlohmann::ordered_json written = searchResultJson(result);
  const SearchResult read = searchResultFromJson(nlohmann::json::parse(written.dump()), "r.json");
  EXPECT_EQ(searchResultJson(read).dump(), written.dump());
  ASSERT_EQ(read.world.visitedViews().size(), 2u);
  EXPECT_DOUBLE_EQ(read.world.visitedViews()[1].base.yaw, -2.0);
  EXPECT_DOUBLE_EQ(read.start.x, 0.5);
  EXPECT_EQ(read.world.foundObjects().at(0).view, 1);
  EXPECT_EQ(read.world.missingObjects("breakfast"), (std::vector<ObjectKey>{{"Plate", "0"}}));
}

TEST(SearchResultJson, AMalformedResultIsRefusedNamingTheField) {
  const nlohmann::json good = nlohmann::json::parse(
      searchResultJson(searchThrough(base(0.5, 0.5), {base(1.5, 1.0), base(2.0, 1.2)})).dump());
  nlohmann::json bad = good;
  bad["outcome"] = "lost";
  EXPECT_NE(inputErrorOf([&] { searchResultFromJson(bad, "r.json"); }).find("lost"),
            std::string::npos);
  bad = good;
  bad["visited"][1].erase("base");
  EXPECT_NE(inputErrorOf([&] { searchResultFromJson(bad, "r.json"); }).find("visited[1].base"),
            std::string::npos);
  bad = good;
  bad["found"][0]["view"] = 9;
  EXPECT_NE(inputErrorOf([&] { searchResultFromJson(bad, "r.json"); }).find("found[0].view"),
            std::string::npos);
  TempDir dir("search_result_bad");
  EXPECT_NE(inputErrorOf([&] { readSearchResult(dir.file("none.json")); }).find("none.json"),
            std::string::npos);
}

}  // namespace
}  // namespace asr_state_machine
