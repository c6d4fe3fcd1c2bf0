// World files and the object catalogue: the issue's example, JSON, defaults from the catalogue,
// every recorded type catalogued, and malformed files refused with the file and field named.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <set>
#include <string>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_common/testing/recordings_skip.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_robot_model/world.hpp"
#include "refused_edit.hpp"

using asr_common::testing::inputErrorOf;
using asr_common::testing::TempDir;
using namespace asr_robot_model;

namespace {

const std::string kExample = ASR_ROBOT_MODEL_TEST_DATA "/issue_example_world.yaml";

std::set<std::string> recordedTypes(const std::string& database) {
  sqlite3* db = nullptr;
  std::set<std::string> types;
  if (sqlite3_open_v2(database.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK) {
    sqlite3_stmt* query = nullptr;
    sqlite3_prepare_v2(db, "SELECT DISTINCT type FROM recorded_objects", -1, &query, nullptr);
    while (query != nullptr && sqlite3_step(query) == SQLITE_ROW)
      types.insert(reinterpret_cast<const char*>(sqlite3_column_text(query, 0)));
    sqlite3_finalize(query);
  }
  sqlite3_close(db);
  return types;
}

// The example with `from` replaced by `to`; the error must name the file and `field`.
void expectRefused(const std::string& from, const std::string& to, const std::string& field) {
  const ObjectCatalogue catalogue = loadObjectCatalogue(defaultObjectCatalogue());
  asr_robot_model::testing::expectEditRefused(
      TempDir("world"), "world.yaml", asr_common::testing::fileBytes(kExample), from, to, field,
      [&](const std::string& path) { loadWorld(path, catalogue); });
}

}  // namespace

TEST(World, TheIssuesExampleReadsAsWritten) {
  const World world = loadWorld(kExample, loadObjectCatalogue(defaultObjectCatalogue()));
  EXPECT_EQ(world.frame, "map");
  EXPECT_EQ(world.room_min, Eigen::Vector2d(-1, -1));
  EXPECT_EQ(world.room_max, Eigen::Vector2d(5, 4));
  ASSERT_EQ(world.furniture.size(), 1u);
  EXPECT_EQ(world.furniture[0].name, "table");
  EXPECT_EQ(world.furniture[0].box.size, Eigen::Vector3d(1.2, 0.8, 0.72));
  ASSERT_EQ(world.objects.size(), 1u);
  EXPECT_EQ(world.objects[0].key, (asr_common::ObjectKey{"Cup", "0"}));
  EXPECT_EQ(world.objects[0].box.pose.position, Eigen::Vector3d(1.8, 1.1, 0.77));
  EXPECT_EQ(world.objects[0].box.size, Eigen::Vector3d(0.08, 0.08, 0.10));
  EXPECT_EQ(world.objects[0].normals.size(), 2u);
}

TEST(World, JsonWorldsAndCatalogueDefaults) {
  TempDir dir("world");
  const std::string path = dir.write("world.json", R"({"version": 1, "frame": "map",
    "room": {"min": [0, 0], "max": [3, 3]},
    "objects": [{"type": "marker_11", "id": 7,
      "pose": {"position": {"x": 1, "y": 1, "z": 1}, "orientation": {"x": 0, "y": 0, "z": 0, "w": 1}}}]})");
  const World world = loadWorld(path, loadObjectCatalogue(defaultObjectCatalogue()));
  ASSERT_EQ(world.objects.size(), 1u);
  EXPECT_EQ(world.objects[0].key.id, "7");
  EXPECT_EQ(world.objects[0].box.size, Eigen::Vector3d(0.06, 0.06, 0.005));
  ASSERT_EQ(world.objects[0].normals.size(), 1u);
  EXPECT_EQ(world.objects[0].normals[0], Eigen::Vector3d::UnitZ());
}

TEST(World, MalformedWorldsNameTheFileAndTheField) {
  expectRefused("version: 1", "version: 2", "version");
  expectRefused("max: [5.0, 4.0]", "max: [-5.0, 4.0]", "room");
  expectRefused("size: [1.2, 0.8, 0.72]", "size: [1.2, 0.8]", "furniture[0].size");
  expectRefused("size: [1.2, 0.8, 0.72]", "size: [1.2, 0, 0.72]", "furniture[0].size");
  expectRefused("y: 1.1, z: 0.77", "y: .nan, z: 0.77", "objects[0].pose.position.y");
  expectRefused("z: 0, w: 1}}\n    size: [0.08", "z: 0, w: 2}}\n    size: [0.08",
                "objects[0].pose.orientation");
  expectRefused(
      "type: Cup\n    id: \"0\"\n    pose: {position: {x: 1.8, y: 1.1, z: 0.77}, "
      "orientation: {x: 0, y: 0, z: 0, w: 1}}\n    size: [0.08, 0.08, 0.10]",
      "type: Teapot\n    id: \"0\"\n    pose: {position: {x: 1.8, y: 1.1, z: 0.77}, "
      "orientation: {x: 0, y: 0, z: 0, w: 1}}",
      "objects[0].type");
  expectRefused("normals: [[1, 0, 0]", "normals: [[0, 0, 0]", "objects[0].normals[0]");
  expectRefused("    id: \"0\"\n", "", "objects[0].id");
  expectRefused("z: 0.77", "z: 0.5", "inside furniture 'table'");
  expectRefused("room: {", "rooms: {", "room");
  expectRefused("robot: {x: 0.0", "robot: {x: abc", "robot.x");
  expectRefused("frame: map", "frame: [", "not valid YAML");
}

TEST(ObjectCatalogue, CoversEveryTypeOfTheShippedRecordings) {
  REQUIRE_RECORDINGS();
  const ObjectCatalogue catalogue = loadObjectCatalogue(defaultObjectCatalogue());
  std::size_t types = 0;
  for (const char* file :
       {"story_1.sqlite", "story_2.sqlite", "office2016.sqlite", "breakfast_merge.sqlite"}) {
    for (const std::string& type : recordedTypes(asr_common::testing::recording(file))) {
      ++types;
      EXPECT_EQ(catalogue.count(type), 1u) << type << " of " << file;
    }
  }
  EXPECT_GT(types, 20u);
}

TEST(ObjectCatalogue, MalformedCatalogueNamesTheType) {
  TempDir dir("catalogue");
  const std::string path =
      dir.write("types.yaml", "version: 1\ntypes:\n  Cup: {size: [0.1, 0.1]}\n");
  const std::string message = inputErrorOf([&] { loadObjectCatalogue(path); });
  EXPECT_NE(message.find(path + ": types.Cup.size"), std::string::npos) << message;
}
