#include "asr_ism/sqlite/demonstration_writer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>

#include "asr_common/testing/input_error_of.hpp"
#include "asr_common/testing/recordings_skip.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_ism/common_types.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism/sqlite/sqlite_database.hpp"
#include "asr_ism/testing/sqlite_dump.hpp"

namespace asr_ism::sqlite {
namespace {

namespace fs = std::filesystem;

using asr_common::testing::fileBytes;
using asr_common::testing::inputErrorOf;
using asr_common::testing::recording;
using asr_common::testing::TempDir;
using testing::Dump;
using testing::dumpFile;

// Old rows are all still there (a changed row would be missing), and `added` rows are new.
void expectRowsKept(const Dump& before, const Dump& after,
                    const std::map<std::string, std::size_t>& added) {
  for (const auto& [table, old_rows] : before.rows) {
    SCOPED_TRACE(table);
    ASSERT_EQ(after.rows.count(table), 1u);
    const auto& new_rows = after.rows.at(table);
    EXPECT_TRUE(std::includes(new_rows.begin(), new_rows.end(), old_rows.begin(), old_rows.end()));
    const auto expected_added = added.count(table) ? added.at(table) : 0u;
    EXPECT_EQ(new_rows.size(), old_rows.size() + expected_added);
  }
}

Pose randomPose(std::mt19937& random) {
  std::uniform_real_distribution<double> uniform(-2.0, 2.0);
  const Eigen::Vector3d axis(uniform(random), uniform(random), uniform(random));
  return Pose(Eigen::Vector3d(uniform(random), uniform(random), uniform(random)),
              Eigen::Quaterniond(Eigen::AngleAxisd(uniform(random), axis.normalized())));
}

// Objects in order of first observation (the order a reader recovers); some steps miss some.
Demonstration syntheticDemonstration(const std::string& scene) {
  const std::vector<ObjectKey> objects = {
      {"Cup", ""}, {"PlateDeep", "018054024100"}, {"PlateDeep", "054042013100"}, {"marker_1", "7"}};
  Demonstration demonstration(scene, objects);
  std::mt19937 random(11);
  for (std::size_t step = 0; step < 6; ++step) {
    demonstration.addStep();
    for (std::size_t object = 0; object < objects.size(); ++object) {
      const bool absent =
          (step == 2 && object == 2) || (step == 3 && object == 0) || (step == 4 && object != 3);
      if (!absent)
        demonstration.setPose(step, object, randomPose(random));
    }
  }
  return demonstration;
}

void expectSameDemonstration(const Demonstration& read, const Demonstration& written) {
  EXPECT_EQ(read.scene(), written.scene());
  ASSERT_EQ(read.objects(), written.objects());
  ASSERT_EQ(read.stepCount(), written.stepCount());
  for (std::size_t step = 0; step < written.stepCount(); ++step) {
    for (std::size_t object = 0; object < written.objectCount(); ++object) {
      SCOPED_TRACE("step " + std::to_string(step) + ", object " + std::to_string(object));
      const auto& expected = written.pose(step, object);
      const auto& actual = read.pose(step, object);
      ASSERT_EQ(actual.has_value(), expected.has_value());
      if (expected) {
        EXPECT_TRUE(approximatelyEqual(*actual, *expected, 1e-12, 1e-12));
      }
    }
  }
}

TEST(DemonstrationWriter, RoundTripThroughANewFile) {
  TempDir dir("asr_writer");
  const std::string path = dir.file("new.sqlite");
  const Demonstration written = syntheticDemonstration("Breakfast");
  appendDemonstration(path, written);
  expectSameDemonstration(readDemonstration(path, "Breakfast"), written);
}

TEST(DemonstrationWriter, RoundTripOfARecording) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_writer");
  const Demonstration recorded = readDemonstration(recording("story_1.sqlite"), "Spuelkorb_3");
  const std::string path = dir.file("copy.sqlite");
  appendDemonstration(path, recorded);
  expectSameDemonstration(readDemonstration(path, "Spuelkorb_3"), recorded);
}

TEST(DemonstrationWriter, NewFileGetsTheOriginalTablesOnly) {
  TempDir dir("asr_writer");
  const std::string path = dir.file("new.sqlite");
  { DemonstrationWriter writer(path); }
  ASSERT_TRUE(fs::exists(path));
  const Dump dump = dumpFile(path);
  std::set<std::string> tables;
  for (const auto& [table, rows] : dump.rows) {
    tables.insert(table);
    EXPECT_TRUE(rows.empty()) << table;
  }
  EXPECT_EQ(tables, (std::set<std::string>{"recorded_patterns", "recorded_sets", "recorded_objects",
                                           "recorded_poses"}));
  // The original tools read columns by name; these are theirs.
  Database db(path, Database::Mode::kReadOnly);
  const std::map<std::string, std::vector<std::string>> columns = {
      {"recorded_patterns", {"id", "name"}},
      {"recorded_sets", {"id", "patternId"}},
      {"recorded_objects", {"id", "type", "observedId", "resourcePath"}},
      {"recorded_poses", {"id", "objectId", "setId", "px", "py", "pz", "qw", "qx", "qy", "qz"}},
  };
  for (const auto& [table, expected] : columns) {
    std::vector<std::string> actual;
    Statement info = db.prepare("PRAGMA table_info(" + table + ")");
    while (info.step())
      actual.push_back(info.columnText(1));
    EXPECT_EQ(actual, expected) << table;
  }
  EXPECT_TRUE(listRecordedScenes(path).empty());
}

TEST(DemonstrationWriter, QuaternionsAreStoredWxyz) {
  TempDir dir("asr_writer");
  const std::string path = dir.file("new.sqlite");
  const Eigen::Quaterniond orientation(0.5, -0.5, 0.5, 0.5);
  DemonstrationWriter(path).appendConfiguration(
      "Pose", {{{"Cup", "1"}, Pose(Eigen::Vector3d(1.0, 2.0, 3.0), orientation)}});
  Database db(path, Database::Mode::kReadOnly);
  Statement row = db.prepare("SELECT px, py, pz, qw, qx, qy, qz FROM recorded_poses");
  ASSERT_TRUE(row.step());
  const double expected[] = {1.0, 2.0, 3.0, 0.5, -0.5, 0.5, 0.5};
  for (int column = 0; column < 7; ++column)
    EXPECT_DOUBLE_EQ(row.columnDouble(column), expected[column]) << column;
}

TEST(DemonstrationWriter, ConfigurationsBecomeSetsInOrder) {
  TempDir dir("asr_writer");
  const std::string path = dir.file("new.sqlite");
  const Demonstration source = syntheticDemonstration("Breakfast");
  DemonstrationWriter writer(path);
  std::int64_t previous_set = -1;
  for (std::size_t step = 0; step < source.stepCount(); ++step) {
    const std::int64_t set = writer.appendConfiguration("Breakfast", source.configuration(step));
    EXPECT_GT(set, previous_set);
    previous_set = set;
    // Each configuration is committed on its own: a reader sees it at once.
    EXPECT_EQ(readDemonstration(path, "Breakfast").stepCount(), step + 1);
  }
  expectSameDemonstration(readDemonstration(path, "Breakfast"), source);
}

TEST(DemonstrationWriter, AppendingToARecordingKeepsEveryRow) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_writer");
  const std::string path = dir.copyOf(recording("story_2.sqlite"));
  const Dump before = dumpFile(path);
  const Demonstration gedeck_before = readDemonstration(path, "gedeck");

  // Known objects (from gedeck) moved a little, plus one the file has never seen.
  Configuration configuration = gedeck_before.configuration(0);
  for (auto& estimate : configuration)
    estimate.pose.position.x() += 0.25;
  configuration.push_back(
      {{"Teapot", "42"},
       Pose(Eigen::Vector3d(0.1, 0.2, 0.3), Eigen::Quaterniond(0.0, 0.0, 0.0, 1.0))});
  const std::int64_t set = DemonstrationWriter(path).appendConfiguration("Tee", configuration);

  const Dump after = dumpFile(path);
  expectRowsKept(before, after,
                 {{"recorded_patterns", 1},
                  {"recorded_sets", 1},
                  {"recorded_objects", 1},
                  {"recorded_poses", configuration.size()}});
  EXPECT_EQ(after.schema, before.schema) << "no table or index may be added or changed";

  const Demonstration tee = readDemonstration(path, "Tee");
  ASSERT_EQ(tee.stepCount(), 1u);
  std::vector<ObjectKey> keys;
  for (const auto& estimate : configuration)
    keys.push_back(estimate.key);
  Demonstration expected("Tee", keys);
  expected.addStep();
  for (std::size_t i = 0; i < configuration.size(); ++i)
    expected.setPose(0, i, configuration[i].pose);
  expectSameDemonstration(tee, expected);

  Database db(path, Database::Mode::kReadOnly);
  Statement pattern = db.prepare(
      "SELECT p.name FROM recorded_sets s JOIN recorded_patterns p ON p.id = s.patternId "
      "WHERE s.id = ?");
  pattern.bind(1, set);
  ASSERT_TRUE(pattern.step());
  EXPECT_EQ(pattern.columnText(0), "Tee");
  // Every other scene reads exactly as before.
  expectSameDemonstration(readDemonstration(path, "gedeck"), gedeck_before);
}

TEST(DemonstrationWriter, ObjectsAreReusedByTypeAndObservedId) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_writer");
  const std::string path = dir.copyOf(recording("story_2.sqlite"));
  const Dump before = dumpFile(path);
  Demonstration gedeck = readDemonstration(path, "gedeck");
  // Absent objects are fine: only three of the eight are in this step.
  Configuration partial = gedeck.configuration(5);
  partial.resize(3);
  DemonstrationWriter(path).appendConfiguration("gedeck", partial);

  const Dump after = dumpFile(path);
  expectRowsKept(before, after, {{"recorded_sets", 1}, {"recorded_poses", 3}});
  const Demonstration extended = readDemonstration(path, "gedeck");
  ASSERT_EQ(extended.stepCount(), gedeck.stepCount() + 1);
  EXPECT_EQ(extended.objects(), gedeck.objects());
  const Configuration last = extended.configuration(extended.stepCount() - 1);
  ASSERT_EQ(last.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(last[i].key, partial[i].key);
    EXPECT_TRUE(approximatelyEqual(last[i].pose, partial[i].pose, 1e-12, 1e-12));
  }
}

TEST(DemonstrationWriter, StepsWithoutObjectsAreSkipped) {
  TempDir dir("asr_writer");
  const std::string path = dir.file("new.sqlite");
  Demonstration demonstration = syntheticDemonstration("Breakfast");
  const std::size_t empty_step = demonstration.addStep();
  appendDemonstration(path, demonstration);
  const Demonstration read = readDemonstration(path, "Breakfast");
  EXPECT_EQ(read.stepCount(), empty_step);

  const std::string untouched = dir.file("untouched.sqlite");
  Demonstration nothing("Nothing", {{"Cup", ""}});
  nothing.addStep();
  EXPECT_NE(inputErrorOf([&] { appendDemonstration(untouched, nothing); }).find("Nothing"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(untouched));
}

TEST(DemonstrationWriter, InvalidConfigurationsWriteNothing) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_writer");
  const std::string path = dir.copyOf(recording("story_2.sqlite"));
  const std::string bytes = fileBytes(path);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Pose good(Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Quaterniond::Identity());
  Pose nan_position = good;
  nan_position.position.y() = nan;
  Pose infinite_position = good;
  infinite_position.position.z() = std::numeric_limits<double>::infinity();
  Pose zero_quaternion = good;
  zero_quaternion.orientation = Eigen::Quaterniond(0.0, 0.0, 0.0, 0.0);
  Pose nan_quaternion = good;
  nan_quaternion.orientation = Eigen::Quaterniond(nan, 0.0, 0.0, 0.0);
  Pose long_quaternion = good;
  long_quaternion.orientation = Eigen::Quaterniond(2.0, 0.0, 0.0, 0.0);

  struct Case {
    const char* name;
    std::string scene;
    Configuration configuration;
    const char* message;
  };
  // The invalid estimate comes last, so a writer that wrote as it went would leave rows behind.
  const std::vector<Case> cases = {
      {"NaN position", "gedeck", {{{"Cup", "1"}, good}, {{"Cup", "2"}, nan_position}}, "finite"},
      {"infinite position", "gedeck", {{{"Cup", "2"}, infinite_position}}, "finite"},
      {"zero quaternion",
       "gedeck",
       {{{"Cup", "1"}, good}, {{"Cup", "2"}, zero_quaternion}},
       "zero quaternion"},
      {"NaN quaternion", "gedeck", {{{"Cup", "2"}, nan_quaternion}}, "finite"},
      {"unnormalised quaternion", "gedeck", {{{"Cup", "2"}, long_quaternion}}, "normalised"},
      {"empty configuration", "gedeck", {}, "empty configuration"},
      {"empty scene", "", {{{"Cup", "1"}, good}}, "scene"},
      {"object twice", "gedeck", {{{"Cup", "1"}, good}, {{"Cup", "1"}, good}}, "twice"},
      {"empty type", "gedeck", {{{"", "1"}, good}}, "empty type"},
  };
  DemonstrationWriter writer(path);
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string message =
        inputErrorOf([&] { writer.appendConfiguration(c.scene, c.configuration); });
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(c.message), std::string::npos) << message;
    EXPECT_EQ(fileBytes(path), bytes);
  }

  // A bad step anywhere in a demonstration writes none of its steps.
  Demonstration demonstration = syntheticDemonstration("Breakfast");
  const std::size_t bad_step = demonstration.addStep();
  demonstration.setPose(bad_step, 1, zero_quaternion);
  demonstration.addStep();
  demonstration.setPose(bad_step + 1, 1, good);
  EXPECT_NE(inputErrorOf([&] { appendDemonstration(path, demonstration); }).find("zero"),
            std::string::npos);
  EXPECT_EQ(fileBytes(path), bytes);
}

TEST(DemonstrationWriter, RefusesFilesThatDoNotFit) {
  TempDir dir("asr_writer");
  const std::string text_file = dir.file("notes.sqlite");
  std::ofstream(text_file) << "not a database\n";
  const std::string text_bytes = fileBytes(text_file);
  EXPECT_NE(inputErrorOf([&] { DemonstrationWriter writer(text_file); }).find(text_file),
            std::string::npos);
  EXPECT_NE(inputErrorOf([&] {
              appendDemonstration(text_file, syntheticDemonstration("Breakfast"));
            }).find(text_file),
            std::string::npos);
  EXPECT_EQ(fileBytes(text_file), text_bytes);

  // recorded_poses without the quaternion columns: a different schema, not ours to extend.
  const std::string other = dir.file("other.sqlite");
  {
    Database db(other, Database::Mode::kReadWriteCreate);
    db.execute(
        "CREATE TABLE recorded_poses (id INTEGER PRIMARY KEY, objectId INTEGER, "
        "setId INTEGER, px FLOAT, py FLOAT, pz FLOAT)");
  }
  const std::string other_bytes = fileBytes(other);
  const std::string message = inputErrorOf([&] { DemonstrationWriter writer(other); });
  EXPECT_NE(message.find(other), std::string::npos) << message;
  EXPECT_NE(message.find("recorded_poses"), std::string::npos) << message;
  EXPECT_NE(message.find("qw, qx, qy, qz"), std::string::npos) << message;
  EXPECT_EQ(fileBytes(other), other_bytes) << "no table may be created in a refused file";
}

}  // namespace
}  // namespace asr_ism::sqlite
