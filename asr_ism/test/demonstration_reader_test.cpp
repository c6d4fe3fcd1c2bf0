#include "asr_ism/sqlite/demonstration_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_common/testing/recordings_skip.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_ism/common_types.hpp"
#include "asr_ism/sqlite/sqlite_database.hpp"

namespace asr_ism::sqlite {
namespace {

namespace fs = std::filesystem;

using asr_common::testing::inputErrorOf;
using asr_common::testing::recording;
using asr_common::testing::recordings;
using asr_common::testing::TempDir;

TEST(DemonstrationReader, ListsTheScenesOfEachRecordingInIdOrder) {
  REQUIRE_RECORDINGS();
  const std::string dir = recordings() + "/";
  EXPECT_EQ(listRecordedScenes(dir + "story_1.sqlite"),
            (std::vector<std::string>{"Gedeck_Ende", "gedeck", "Gedeck_Schrank_2", "Spuelkorb_3"}));
  EXPECT_EQ(listRecordedScenes(dir + "story_2.sqlite"),
            (std::vector<std::string>{"Brot_Gedeck_2", "Brot_Regal", "Gedeck_Ende", "gedeck",
                                      "Getraenke_Gedeck", "Getraenke_Regal", "Muesli_Gedeck",
                                      "Muesli_Regal", "Vertauschen_2"}));
  EXPECT_EQ(listRecordedScenes(dir + "office2016.sqlite"),
            (std::vector<std::string>{"office2016"}));
  EXPECT_EQ(listRecordedScenes(dir + "breakfast_merge.sqlite"),
            (std::vector<std::string>{"scene_a", "scene_b"}));
}

TEST(DemonstrationReader, SetAndObjectCountsMatchTheRecordingsTable) {
  REQUIRE_RECORDINGS();
  struct Expected {
    const char* file;
    const char* scene;
    std::size_t sets;
    std::size_t objects;
  };
  // The table in the recordings' README.
  const Expected expected[] = {
      {"story_1.sqlite", "gedeck", 112, 8},           {"story_1.sqlite", "Gedeck_Ende", 220, 8},
      {"story_1.sqlite", "Gedeck_Schrank_2", 103, 9}, {"story_1.sqlite", "Spuelkorb_3", 117, 10},
      {"story_2.sqlite", "Brot_Gedeck_2", 92, 5},     {"story_2.sqlite", "Brot_Regal", 98, 6},
      {"story_2.sqlite", "Getraenke_Gedeck", 23, 3},  {"story_2.sqlite", "Getraenke_Regal", 44, 4},
      {"story_2.sqlite", "Muesli_Gedeck", 26, 4},     {"story_2.sqlite", "Muesli_Regal", 98, 5},
      {"story_2.sqlite", "Vertauschen_2", 48, 4},     {"story_2.sqlite", "gedeck", 112, 8},
      {"story_2.sqlite", "Gedeck_Ende", 220, 8},      {"office2016.sqlite", "office2016", 51, 4},
      {"breakfast_merge.sqlite", "scene_a", 20, 4},   {"breakfast_merge.sqlite", "scene_b", 20, 5},
  };
  for (const auto& row : expected) {
    SCOPED_TRACE(std::string(row.file) + " " + row.scene);
    const Demonstration demonstration = readDemonstration(recordings() + "/" + row.file, row.scene);
    EXPECT_EQ(demonstration.scene(), row.scene);
    EXPECT_EQ(demonstration.stepCount(), row.sets);
    EXPECT_EQ(demonstration.objectCount(), row.objects);
  }
}

TEST(DemonstrationReader, InstancesOfOneTypeStayApart) {
  REQUIRE_RECORDINGS();
  const Demonstration demonstration =
      readDemonstration(recordings() + "/story_1.sqlite", "Spuelkorb_3");
  std::vector<std::string> plate_ids;
  for (const auto& key : demonstration.objects()) {
    if (key.type == "PlateDeep")
      plate_ids.push_back(key.id);
  }
  ASSERT_EQ(plate_ids.size(), 2u);
  EXPECT_NE(plate_ids[0], plate_ids[1]);
  EXPECT_GE(demonstration.indexOf({"PlateDeep", "018054024100"}), 0);
  EXPECT_GE(demonstration.indexOf({"PlateDeep", "054042013100"}), 0);
}

TEST(DemonstrationReader, PosesEqualTheRowsInIdOrder) {
  REQUIRE_RECORDINGS();
  const std::string path = recordings() + "/story_1.sqlite";
  const Demonstration demonstration = readDemonstration(path, "gedeck");

  // Every pose row of the scene, read independently of the reader.
  Database db(path, Database::Mode::kReadOnly);
  std::map<std::int64_t, std::size_t> step_of_set;
  Statement sets = db.prepare(
      "SELECT s.id FROM recorded_sets s JOIN recorded_patterns p ON p.id = s.patternId "
      "WHERE p.name = 'gedeck' ORDER BY s.id");
  while (sets.step())
    step_of_set.emplace(sets.columnInt(0), step_of_set.size());
  Statement rows = db.prepare(
      "SELECT q.setId, o.type, o.observedId, q.px, q.py, q.pz, q.qw, q.qx, q.qy, q.qz "
      "FROM recorded_poses q JOIN recorded_objects o ON o.id = q.objectId "
      "JOIN recorded_sets s ON s.id = q.setId JOIN recorded_patterns p ON p.id = s.patternId "
      "WHERE p.name = 'gedeck' ORDER BY q.id");
  std::size_t row_count = 0;
  bool first = true;
  while (rows.step()) {
    ++row_count;
    const std::size_t step = step_of_set.at(rows.columnInt(0));
    const int object = demonstration.indexOf({rows.columnText(1), rows.columnText(2)});
    ASSERT_GE(object, 0);
    if (first) {
      // The first row is the first observation of the first set and of the first object.
      EXPECT_EQ(step, 0u);
      EXPECT_EQ(object, 0);
      first = false;
    }
    const auto& pose = demonstration.pose(step, static_cast<std::size_t>(object));
    ASSERT_TRUE(pose.has_value());
    EXPECT_EQ(pose->position,
              Eigen::Vector3d(rows.columnDouble(3), rows.columnDouble(4), rows.columnDouble(5)));
    // Stored quaternions are close to unit length; the reader canonicalises them.
    const Eigen::Quaterniond stored(rows.columnDouble(6), rows.columnDouble(7),
                                    rows.columnDouble(8), rows.columnDouble(9));
    EXPECT_EQ(pose->orientation.coeffs(), canonicalQuaternion(stored).coeffs());
  }
  std::size_t observed = 0;
  for (std::size_t step = 0; step < demonstration.stepCount(); ++step)
    observed += demonstration.configuration(step).size();
  EXPECT_EQ(observed, row_count);
}

TEST(DemonstrationReaderErrors, MissingFileIsNamed) {
  TempDir dir("asr_reader");
  const std::string path = dir.file("absent.sqlite");
  EXPECT_NE(inputErrorOf([&] { readDemonstration(path, "gedeck"); }).find(path), std::string::npos);
  EXPECT_NE(inputErrorOf([&] { listRecordedScenes(path); }).find(path), std::string::npos);
  EXPECT_FALSE(fs::exists(path)) << "reading must not create the file";
}

TEST(DemonstrationReaderErrors, NonSqliteFileIsNamed) {
  TempDir dir("asr_reader");
  const std::string path = dir.file("notes.sqlite");
  std::ofstream(path) << "this is a text file, not a database\n";
  const std::string message = inputErrorOf([&] { readDemonstration(path, "gedeck"); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("not an SQLite database"), std::string::npos) << message;
}

TEST(DemonstrationReaderErrors, SqliteFileWithoutRecordedTablesIsNamed) {
  TempDir dir("asr_reader");
  const std::string path = dir.file("other.sqlite");
  {
    Database db(path, Database::Mode::kReadWriteCreate);
    db.execute("CREATE TABLE unrelated (id INTEGER PRIMARY KEY, value TEXT)");
  }
  const std::string message = inputErrorOf([&] { readDemonstration(path, "gedeck"); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("recorded_"), std::string::npos) << message;
  EXPECT_NE(inputErrorOf([&] { listRecordedScenes(path); }).find(path), std::string::npos);
}

TEST(DemonstrationReaderErrors, UnknownSceneListsTheKnownOnes) {
  REQUIRE_RECORDINGS();
  const std::string path = recordings() + "/story_1.sqlite";
  const std::string message = inputErrorOf([&] { readDemonstration(path, "Kitchen_Sink"); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("Kitchen_Sink"), std::string::npos) << message;
  for (const char* known : {"Gedeck_Ende", "gedeck", "Gedeck_Schrank_2", "Spuelkorb_3"})
    EXPECT_NE(message.find(known), std::string::npos) << message;
}

std::int64_t firstGedeckPoseId(const std::string& path) {
  Database db(path, Database::Mode::kReadOnly);
  Statement first = db.prepare(
      "SELECT min(q.id) FROM recorded_poses q JOIN recorded_sets s ON s.id = q.setId "
      "JOIN recorded_patterns p ON p.id = s.patternId WHERE p.name = 'gedeck'");
  first.step();
  return first.columnInt(0);
}

// Changes the first pose row of gedeck in a copy of story_1 and returns that row's id.
std::int64_t changeFirstGedeckPose(const std::string& path, const std::string& assignments) {
  const std::int64_t id = firstGedeckPoseId(path);
  Database db(path, Database::Mode::kReadWriteCreate);
  db.execute("UPDATE recorded_poses SET " + assignments + " WHERE id = " + std::to_string(id));
  return id;
}

TEST(DemonstrationReaderErrors, NanPoseRowIsNamed) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_reader");
  const std::string path = dir.copyOf(recording("story_1.sqlite"));
  const std::int64_t id = firstGedeckPoseId(path);
  {
    // SQLite keeps no NaN: binding one stores NULL, which is what a NaN recording leaves.
    Database db(path, Database::Mode::kReadWriteCreate);
    Statement update = db.prepare("UPDATE recorded_poses SET py = ? WHERE id = ?");
    update.bind(1, std::numeric_limits<double>::quiet_NaN()).bind(2, id).execute();
  }
  const std::string message = inputErrorOf([&] { readDemonstration(path, "gedeck"); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("recorded_poses id " + std::to_string(id)), std::string::npos) << message;
  // Other scenes of the file are unaffected.
  EXPECT_NO_THROW(readDemonstration(path, "Gedeck_Ende"));
}

TEST(DemonstrationReaderErrors, InfinitePoseRowIsNamed) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_reader");
  const std::string path = dir.copyOf(recording("story_1.sqlite"));
  const std::int64_t id = changeFirstGedeckPose(path, "pz = 1e999");
  const std::string message = inputErrorOf([&] { readDemonstration(path, "gedeck"); });
  EXPECT_NE(message.find("recorded_poses id " + std::to_string(id)), std::string::npos) << message;
  EXPECT_NE(message.find("not finite"), std::string::npos) << message;
}

TEST(DemonstrationReaderErrors, TextInAPoseColumnIsNamed) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_reader");
  const std::string path = dir.copyOf(recording("story_1.sqlite"));
  // SQLite would silently read such text as 0.
  const std::int64_t id = changeFirstGedeckPose(path, "px = 'not a number'");
  const std::string message = inputErrorOf([&] { readDemonstration(path, "gedeck"); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("recorded_poses id " + std::to_string(id)), std::string::npos) << message;
}

TEST(DemonstrationReaderErrors, ZeroQuaternionRowIsNamed) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_reader");
  const std::string path = dir.copyOf(recording("story_1.sqlite"));
  const std::int64_t id = changeFirstGedeckPose(path, "qw = 0, qx = 0, qy = 0, qz = 0");
  const std::string message = inputErrorOf([&] { readDemonstration(path, "gedeck"); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("recorded_poses id " + std::to_string(id)), std::string::npos) << message;
  EXPECT_NE(message.find("zero quaternion"), std::string::npos) << message;
}

TEST(DemonstrationReaderErrors, SceneWithoutSetsIsAnEmptyDemonstration) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_reader");
  const std::string path = dir.copyOf(recording("story_1.sqlite"));
  {
    Database db(path, Database::Mode::kReadWriteCreate);
    db.execute("INSERT INTO recorded_patterns (name) VALUES ('Empty_Scene')");
  }
  const std::string message = inputErrorOf([&] { readDemonstration(path, "Empty_Scene"); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("Empty_Scene"), std::string::npos) << message;
  // The scene is listed nonetheless: it exists, it just has nothing to learn from.
  const auto scenes = listRecordedScenes(path);
  EXPECT_EQ(scenes.back(), "Empty_Scene");
}

TEST(DemonstrationReaderErrors, PoseOfAnUnknownObjectIsNamed) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_reader");
  const std::string path = dir.copyOf(recording("story_1.sqlite"));
  const std::int64_t id = changeFirstGedeckPose(path, "objectId = 999999");
  const std::string message = inputErrorOf([&] { readDemonstration(path, "gedeck"); });
  EXPECT_NE(message.find("recorded_poses id " + std::to_string(id)), std::string::npos) << message;
  EXPECT_NE(message.find("999999"), std::string::npos) << message;
}

}  // namespace
}  // namespace asr_ism::sqlite
