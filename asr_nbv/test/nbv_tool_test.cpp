// `asr nbv` run as a user runs it: predicted clouds in, the view to take out as JSON.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "asr_common/testing/tool_run.hpp"

namespace {

using asr_common::testing::runTool;
using asr_common::testing::TempDir;
using nlohmann::json;

std::string write(const TempDir& dir, const std::string& name, const std::string& text) {
  const std::string path = dir.file(name);
  std::ofstream(path) << text;
  return path;
}

const char* const kWorld = R"(version: 1
frame: map
room: {min: [0.0, 0.0], max: [6.0, 5.0]}
furniture:
  - name: table
    pose: {position: {x: 4.5, y: 2.5, z: 0.36}, orientation: {x: 0, y: 0, z: 0, w: 1}}
    size: [1.0, 0.8, 0.72]
robot: {x: 1.0, y: 1.0, yaw: 0.0, pan: 0.0, tilt: 0.0}
)";

// Predicted cups on the table (Cup: no normals in the shipped catalogue, seen from every side),
// one pose of an unknown type and one with a NaN (null) coordinate.
std::string clouds() {
  json poses = json::array();
  for (int i = 0; i < 20; ++i)
    poses.push_back({{"position", {{"x", 4.3 + 0.02 * i}, {"y", 2.5}, {"z", 0.78}}},
                     {"orientation", {{"x", 0}, {"y", 0}, {"z", 0}, {"w", 1}}}});
  json broken = poses[0];
  broken["position"]["x"] = nullptr;
  json document = {{"scene", "breakfast"},
                   {"predictions",
                    {{{"type", "Cup"}, {"id", "0"}, {"poses", poses}},
                     {{"type", "Mystery"}, {"id", "1"}, {"poses", {poses[3], broken}}}}}};
  return document.dump();
}

TEST(NbvTool, FindsAViewOfThePredictedCups) {
  TempDir dir("nbv_tool");
  const auto run = runTool(
      NBV_TOOL, dir,
      {"--world", write(dir, "world.yaml", kWorld), "--clouds", write(dir, "clouds.json", clouds()),
       "--state", "1 1 0 0 0", "--seed", "3", "--json"});
  EXPECT_EQ(run.exit_code, 0) << asr_common::testing::describe(run);
  // The unknown type and the rejected pose are warned about, by name.
  bool named = false;
  for (const std::string& line : run.err)
    named = named || line.find("'Mystery'") != std::string::npos;
  EXPECT_TRUE(named) << asr_common::testing::describe(run);
  const json out = json::parse(run.out);
  ASSERT_TRUE(out["found"].get<bool>()) << run.out;
  EXPECT_EQ(out["hypotheses"].get<int>(), 21);
  EXPECT_EQ(out["rejected_poses"].get<int>(), 1);
  EXPECT_GT(out["utility"].get<double>(), 0.0);
  EXPECT_GT(out["candidates_rated"].get<int>(), 0);
  const json& view = out["view"];
  for (const char* key : {"x", "y", "yaw", "pan", "tilt"})
    EXPECT_TRUE(view["state"].contains(key)) << key;
  EXPECT_FALSE(view["types"].empty());
  // The camera is within the far plane of the cups.
  const double dx = view["camera"]["position"]["x"].get<double>() - 4.5;
  const double dy = view["camera"]["position"]["y"].get<double>() - 2.5;
  EXPECT_LT(std::hypot(dx, dy), 1.5);

  // Visiting that view with its types leaves less to see there: the next view differs.
  json visited = json::array({{{"camera", view["camera"]}, {"types", view["types"]}}});
  const auto again = runTool(NBV_TOOL, dir,
                             {"--world", dir.file("world.yaml"), "--clouds",
                              dir.file("clouds.json"), "--state", "1 1 0 0 0", "--seed", "3",
                              "--visited", write(dir, "visited.json", visited.dump()), "--json"});
  EXPECT_EQ(again.exit_code, 0) << asr_common::testing::describe(again);
  const json next = json::parse(again.out);
  if (next["found"].get<bool>()) {
    EXPECT_NE(next["view"]["camera"], view["camera"]);
  }
}

TEST(NbvTool, EmptyCloudsAreNothingToSearch) {
  TempDir dir("nbv_tool");
  const auto run = runTool(
      NBV_TOOL, dir,
      {"--world", write(dir, "world.yaml", kWorld), "--clouds",
       write(dir, "clouds.json", R"({"predictions": [{"type": "Cup", "id": "0", "poses": []}]})"),
       "--json"});
  asr_common::testing::expectSuccess(run);
  EXPECT_FALSE(json::parse(run.out)["found"].get<bool>());
}

TEST(NbvTool, BadInputIsOneLineNamingIt) {
  TempDir dir("nbv_tool");
  const std::string world = write(dir, "world.yaml", kWorld);
  const auto missing =
      runTool(NBV_TOOL, dir, {"--world", world, "--clouds", dir.file("none.json"), "--json"});
  EXPECT_EQ(missing.exit_code, 1);
  ASSERT_EQ(missing.err.size(), 1u) << asr_common::testing::describe(missing);
  EXPECT_NE(missing.err[0].find("none.json"), std::string::npos);
  EXPECT_TRUE(missing.out.empty());
  const auto state = runTool(
      NBV_TOOL, dir,
      {"--world", world, "--clouds", write(dir, "c.json", clouds()), "--state", "1 nan 0 0 0"});
  EXPECT_EQ(state.exit_code, 2);
  const auto usage = runTool(NBV_TOOL, dir, {"--clouds", dir.file("c.json")});
  EXPECT_EQ(usage.exit_code, 2);
}

}  // namespace
