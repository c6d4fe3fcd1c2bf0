#include "asr_ism_tree/sqlite/model_store.hpp"

#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>

#include "asr_common/input_error.hpp"
#include "asr_common/testing/input_error_of.hpp"
#include "asr_common/testing/recordings_skip.hpp"
#include "asr_common/testing/temp_dir.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"
#include "asr_ism/sqlite/sqlite_database.hpp"
#include "asr_ism/testing/sqlite_dump.hpp"
#include "asr_ism_tree/star_center.hpp"
#include "asr_ism_tree/tree_generation.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"

namespace asr_ism_tree::sqlite {
namespace {

namespace fs = std::filesystem;
using asr_common::InputError;
using asr_common::testing::fileBytes;
using asr_common::testing::inputErrorOf;
using asr_common::testing::recording;
using asr_common::testing::TempDir;
using asr_ism::Demonstration;
using asr_ism::sqlite::Database;
using asr_ism::sqlite::Statement;
using asr_ism::testing::Dump;
using asr_ism::testing::dumpFile;
using asr_ism::testing::queryRows;

// ---- bit-exact comparisons ----

bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

void expectSamePose(const asr_common::Pose& a, const asr_common::Pose& b, const std::string& what) {
  for (int i = 0; i < 3; ++i)
    EXPECT_TRUE(sameBits(a.position[i], b.position[i])) << what << " position " << i;
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(sameBits(a.orientation.coeffs()[i], b.orientation.coeffs()[i]))
        << what << " orientation " << i;
  }
}

void expectSameTree(const IsmTree& loaded, const IsmTree& learned) {
  EXPECT_EQ(loaded.scene, learned.scene);
  EXPECT_TRUE(sameBits(loaded.parameters.bin_size, learned.parameters.bin_size));
  EXPECT_TRUE(
      sameBits(loaded.parameters.max_angle_deviation, learned.parameters.max_angle_deviation));
  EXPECT_EQ(loaded.topology, learned.topology);
  EXPECT_EQ(loaded.topology.relations(), learned.topology.relations());
  EXPECT_EQ(loaded.parent, learned.parent);
  EXPECT_EQ(loaded.level, learned.level);
  ASSERT_EQ(loaded.isms.size(), learned.isms.size());
  for (std::size_t i = 0; i < learned.isms.size(); ++i) {
    const auto& a = loaded.isms[i];
    const auto& b = learned.isms[i];
    SCOPED_TRACE("ISM " + b.name);
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.reference, b.reference);
    ASSERT_EQ(a.members.size(), b.members.size());
    for (std::size_t m = 0; m < b.members.size(); ++m) {
      SCOPED_TRACE("member " + b.members[m].object.toString());
      EXPECT_EQ(a.members[m].object, b.members[m].object);
      EXPECT_EQ(a.members[m].child_ism, b.members[m].child_ism);
      ASSERT_EQ(a.members[m].relative_poses.size(), b.members[m].relative_poses.size());
      for (std::size_t r = 0; r < b.members[m].relative_poses.size(); ++r) {
        expectSamePose(a.members[m].relative_poses[r].reference_in_member,
                       b.members[m].relative_poses[r].reference_in_member,
                       "relative pose " + std::to_string(r));
        EXPECT_EQ(a.members[m].relative_poses[r].step_count,
                  b.members[m].relative_poses[r].step_count);
      }
    }
  }
}

void expectSameInstances(const std::vector<SceneInstance>& a, const std::vector<SceneInstance>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    SCOPED_TRACE("instance " + std::to_string(i));
    EXPECT_EQ(a[i].scene, b[i].scene);
    EXPECT_TRUE(sameBits(a[i].confidence, b[i].confidence));
    expectSamePose(a[i].pose, b[i].pose, "instance pose");
    EXPECT_EQ(a[i].missing, b[i].missing);
    ASSERT_EQ(a[i].objects.size(), b[i].objects.size());
    for (std::size_t o = 0; o < a[i].objects.size(); ++o) {
      const auto& x = a[i].objects[o];
      const auto& y = b[i].objects[o];
      EXPECT_EQ(x.key, y.key);
      EXPECT_EQ(x.estimate, y.estimate);
      EXPECT_EQ(x.appearances, y.appearances);
      EXPECT_TRUE(sameBits(x.similarity, y.similarity));
      EXPECT_TRUE(sameBits(x.position_compliance, y.position_compliance));
      EXPECT_TRUE(sameBits(x.orientation_compliance, y.orientation_compliance));
      expectSamePose(x.pose, y.pose, "object pose");
    }
    ASSERT_EQ(a[i].isms.size(), b[i].isms.size());
    for (std::size_t k = 0; k < a[i].isms.size(); ++k) {
      EXPECT_EQ(a[i].isms[k].name, b[i].isms[k].name);
      EXPECT_EQ(a[i].isms[k].recognized, b[i].isms[k].recognized);
      EXPECT_TRUE(sameBits(a[i].isms[k].objective, b[i].isms[k].objective));
      if (b[i].isms[k].recognized)
        expectSamePose(a[i].isms[k].reference_pose, b[i].isms[k].reference_pose, "ISM pose");
    }
  }
}

// The rows of one stored tree in the suite's per-tree tables.
std::map<std::string, std::vector<std::string>> treeRows(const std::string& path,
                                                         std::int64_t tree_id) {
  sqlite3* db = nullptr;
  EXPECT_EQ(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
  std::map<std::string, std::vector<std::string>> rows;
  for (const char* table : {"asr_ism_objects", "asr_ism_relations", "asr_ism_isms",
                            "asr_ism_members", "asr_ism_relative_poses"}) {
    rows[table] = queryRows(
        db, std::string("SELECT * FROM ") + table + " WHERE tree_id = " + std::to_string(tree_id));
    EXPECT_FALSE(rows[table].empty()) << table;
  }
  sqlite3_close(db);
  return rows;
}

// ---- learned trees (each learned once per test program) ----

struct Learned {
  Demonstration demonstration;
  IsmTree tree;
};

const Learned& starGedeck() {
  static const Learned learned = [] {
    Learned result;
    result.demonstration =
        asr_ism::sqlite::readDemonstration(recording("story_1.sqlite"), "gedeck");
    const auto& objects = result.demonstration.objects();
    result.tree = generateIsmTree(
        result.demonstration,
        RelationTopology::star(objects, chooseStarCenter(result.demonstration)), {});
    return result;
  }();
  return learned;
}

const Learned& completeGedeck() {
  static const Learned learned = [] {
    Learned result;
    result.demonstration = starGedeck().demonstration;
    result.tree = generateIsmTree(result.demonstration,
                                  RelationTopology::complete(result.demonstration.objects()), {});
    return result;
  }();
  return learned;
}

const Learned& completeOffice() {
  static const Learned learned = [] {
    Learned result;
    result.demonstration =
        asr_ism::sqlite::readDemonstration(recording("office2016.sqlite"), "office2016");
    result.tree = generateIsmTree(result.demonstration,
                                  RelationTopology::complete(result.demonstration.objects()), {});
    return result;
  }();
  return learned;
}

// Configurations to recognise: single demonstration steps, and two steps shown at once (two
// overlapping candidate instances), so several instances and partial matches occur.
std::vector<asr_common::Configuration> testConfigurations(const Demonstration& demonstration) {
  std::vector<asr_common::Configuration> configurations;
  const std::size_t last = demonstration.stepCount() - 1;
  for (std::size_t step : {std::size_t{0}, last / 2, last})
    configurations.push_back(demonstration.configuration(step));
  asr_common::Configuration both = demonstration.configuration(0);
  for (auto estimate : demonstration.configuration(last)) {
    estimate.pose.position.x() += 0.05;
    both.push_back(estimate);
  }
  configurations.push_back(both);
  asr_common::Configuration partial = demonstration.configuration(last / 3);
  partial.resize(partial.size() / 2);
  configurations.push_back(partial);
  return configurations;
}

void expectLoadedTreeBehavesAsLearned(const Learned& learned, bool recognise) {
  TempDir dir("asr_model_store");
  const std::string path = dir.file("model.sqlite");
  saveIsmTree(path, learned.tree, "test");
  const IsmTree loaded = loadIsmTree(path, learned.tree.scene);
  expectSameTree(loaded, learned.tree);
  if (!recognise)
    return;
  const TreeRecognizer from_learned(learned.tree);
  const TreeRecognizer from_loaded(loaded);
  std::size_t instances = 0;
  for (const auto& configuration : testConfigurations(learned.demonstration)) {
    const auto expected = from_learned.recognize(configuration);
    instances += expected.size();
    expectSameInstances(from_loaded.recognize(configuration), expected);
  }
  EXPECT_GT(instances, 0u) << "the comparison must cover some instances";
}

TEST(ModelStore, StarTreeLoadsBitForBitAndRecognisesAlike) {
  REQUIRE_RECORDINGS();
  ASSERT_GT(starGedeck().tree.isms.size(), 0u);
  expectLoadedTreeBehavesAsLearned(starGedeck(), true);
}

TEST(ModelStore, CompleteTreeLoadsBitForBit) {
  REQUIRE_RECORDINGS();
  ASSERT_GT(completeGedeck().tree.height(), 1) << "a complete topology needs sub-ISMs";
  expectLoadedTreeBehavesAsLearned(completeGedeck(), false);
}

TEST(ModelStore, CompleteTreeRecognisesAlikeAfterLoading) {
  REQUIRE_RECORDINGS();
  ASSERT_GT(completeOffice().tree.height(), 1);
  expectLoadedTreeBehavesAsLearned(completeOffice(), true);
}

TEST(ModelStore, SavingIntoARecordingKeepsEveryTable) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_model_store");
  const std::string path = dir.copyOf(recording("story_1.sqlite"));
  const Dump before = dumpFile(path);
  ASSERT_TRUE(before.rows.count("model_votes"));
  ASSERT_GT(before.rows.at("model_votes").size(), 0u);

  saveIsmTree(path, starGedeck().tree, "story_1.sqlite");
  const Dump after = dumpFile(path);
  for (const auto& [table, rows] : before.rows) {
    ASSERT_TRUE(after.rows.count(table)) << table;
    EXPECT_EQ(after.rows.at(table), rows) << table;
  }
  for (const auto& [name, sql] : before.schema) {
    ASSERT_TRUE(after.schema.count(name)) << name;
    EXPECT_EQ(after.schema.at(name), sql) << name;
  }
  for (const auto& [name, sql] : after.schema) {
    if (!before.schema.count(name)) {
      EXPECT_TRUE(name.rfind("asr_ism_", 0) == 0 || name.rfind("sqlite_autoindex_asr_ism_", 0) == 0)
          << "unexpected new table or index " << name;
    }
  }
  // The file still works for both purposes.
  EXPECT_EQ(asr_ism::sqlite::readDemonstration(path, "gedeck").stepCount(), 112u);
  expectSameTree(loadIsmTree(path, "gedeck"), starGedeck().tree);
}

std::size_t rowCount(const std::string& path, const std::string& table) {
  Database db(path, Database::Mode::kReadOnly);
  Statement count = db.prepare("SELECT count(*) FROM " + table);
  count.step();
  return static_cast<std::size_t>(count.columnInt(0));
}

TEST(ModelStore, SavingASceneAgainReplacesOnlyThatScene) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_model_store");
  const std::string path = dir.file("models.sqlite");
  saveIsmTree(path, starGedeck().tree, "first");
  saveIsmTree(path, completeOffice().tree, "second");
  EXPECT_EQ(listModelScenes(path), (std::vector<std::string>{"gedeck", "office2016"}));

  std::int64_t office_id;
  {
    Database db(path, Database::Mode::kReadOnly);
    Statement id = db.prepare("SELECT id FROM asr_ism_trees WHERE scene = 'office2016'");
    ASSERT_TRUE(id.step());
    office_id = id.columnInt(0);
  }
  const auto office_before = treeRows(path, office_id);

  saveIsmTree(path, completeGedeck().tree, "third");
  // First-stored order stays; no duplicate scene.
  EXPECT_EQ(listModelScenes(path), (std::vector<std::string>{"gedeck", "office2016"}));
  expectSameTree(loadIsmTree(path, "gedeck"), completeGedeck().tree);
  expectSameTree(loadIsmTree(path, "office2016"), completeOffice().tree);
  EXPECT_EQ(treeRows(path, office_id), office_before);

  // Nothing of the replaced model is left behind.
  EXPECT_EQ(rowCount(path, "asr_ism_relative_poses"),
            completeGedeck().tree.relativePoseCount() + completeOffice().tree.relativePoseCount());
  EXPECT_EQ(rowCount(path, "asr_ism_isms"),
            completeGedeck().tree.isms.size() + completeOffice().tree.isms.size());
  EXPECT_EQ(rowCount(path, "asr_ism_trees"), 2u);
}

TEST(ModelStore, ListModelScenes) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_model_store");
  const std::string copy = dir.copyOf(recording("story_1.sqlite"));
  EXPECT_TRUE(listModelScenes(copy).empty()) << "model_* tables are not this suite's models";
  const std::string path = dir.file("models.sqlite");
  saveIsmTree(path, completeOffice().tree, "test");
  EXPECT_EQ(listModelScenes(path), (std::vector<std::string>{"office2016"}));
  saveIsmTree(path, starGedeck().tree, "test");
  EXPECT_EQ(listModelScenes(path), (std::vector<std::string>{"office2016", "gedeck"}));
}

TEST(ModelStore, NewerSchemaVersionIsRefusedAndLeftUnchanged) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_model_store");
  const std::string path = dir.file("models.sqlite");
  saveIsmTree(path, completeOffice().tree, "test");
  {
    Database db(path, Database::Mode::kReadWriteCreate);
    db.execute("UPDATE asr_ism_schema SET version = 99");
  }
  const std::string bytes = fileBytes(path);
  const std::string message = inputErrorOf([&] { saveIsmTree(path, starGedeck().tree, "test"); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("99"), std::string::npos) << message;
  EXPECT_EQ(fileBytes(path), bytes);
  EXPECT_NE(inputErrorOf([&] { loadIsmTree(path, "office2016"); }).find("99"), std::string::npos);
  EXPECT_NE(inputErrorOf([&] { listModelScenes(path); }).find("99"), std::string::npos);
  EXPECT_EQ(fileBytes(path), bytes);
}

TEST(ModelStore, NonSqliteFileIsRefusedAndLeftByteIdentical) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_model_store");
  const std::string path = dir.file("notes.sqlite");
  std::ofstream(path) << "my notes, not a database\n";
  const std::string bytes = fileBytes(path);
  const std::string message =
      inputErrorOf([&] { saveIsmTree(path, completeOffice().tree, "test"); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_EQ(fileBytes(path), bytes);
  EXPECT_NE(inputErrorOf([&] { loadIsmTree(path, "office2016"); }).find(path), std::string::npos);
  EXPECT_EQ(fileBytes(path), bytes);
}

TEST(ModelStore, InvalidTreeWritesNothing) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_model_store");
  IsmTree broken = completeGedeck().tree;
  ASSERT_GT(broken.isms.size(), 1u);
  broken.parent[1] = static_cast<int>(broken.isms.size()) + 5;  // a child link to nowhere

  const std::string absent = dir.file("absent.sqlite");
  EXPECT_THROW(saveIsmTree(absent, broken, "test"), InputError);
  EXPECT_FALSE(fs::exists(absent));

  const std::string path = dir.file("models.sqlite");
  saveIsmTree(path, completeGedeck().tree, "test");
  const std::string bytes = fileBytes(path);
  EXPECT_THROW(saveIsmTree(path, broken, "test"), InputError);
  EXPECT_EQ(fileBytes(path), bytes);
}

TEST(ModelStore, FailureMidwayLeavesTheFileUnchanged) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_model_store");
  const std::string path = dir.copyOf(recording("story_1.sqlite"));
  saveIsmTree(path, starGedeck().tree, "first");
  {
    // Makes the replacing save fail after it has removed the old model and written part of the
    // new one, as a full disk or a crash would.
    Database db(path, Database::Mode::kReadWriteCreate);
    db.execute(
        "CREATE TRIGGER fail_midway BEFORE INSERT ON asr_ism_relative_poses "
        "WHEN NEW.ism = 1 AND NEW.position = 2 BEGIN SELECT RAISE(ABORT, 'injected failure'); "
        "END");
  }
  const std::string bytes = fileBytes(path);
  const std::string message =
      inputErrorOf([&] { saveIsmTree(path, completeGedeck().tree, "second"); });
  EXPECT_NE(message.find("injected failure"), std::string::npos) << message;
  EXPECT_EQ(fileBytes(path), bytes);
  expectSameTree(loadIsmTree(path, "gedeck"), starGedeck().tree);
  EXPECT_FALSE(fs::exists(path + "-journal")) << "no hot journal may be left behind";
}

TEST(ModelStore, ReadOnlyFileIsLeftUnchanged) {
  REQUIRE_RECORDINGS();
  if (::geteuid() == 0)
    GTEST_SKIP() << "running as root: file permissions do not stop writes";
  TempDir dir("asr_model_store");
  const std::string path = dir.copyOf(recording("story_1.sqlite"));
  fs::permissions(path, fs::perms::owner_read);
  const std::string bytes = fileBytes(path);
  EXPECT_THROW(saveIsmTree(path, starGedeck().tree, "test"), InputError);
  EXPECT_EQ(fileBytes(path), bytes);
}

TEST(ModelStoreErrors, MissingFileIsNamed) {
  TempDir dir("asr_model_store");
  const std::string path = dir.file("absent.sqlite");
  EXPECT_NE(inputErrorOf([&] { loadIsmTree(path, "gedeck"); }).find(path), std::string::npos);
  EXPECT_NE(inputErrorOf([&] { listModelScenes(path); }).find(path), std::string::npos);
  EXPECT_FALSE(fs::exists(path));
}

TEST(ModelStoreErrors, FileWithoutModelsIsNamed) {
  REQUIRE_RECORDINGS();
  const std::string path = recording("story_1.sqlite");
  const std::string message = inputErrorOf([&] { loadIsmTree(path, "gedeck"); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("no ISM tree model"), std::string::npos) << message;
}

TEST(ModelStoreErrors, UnknownSceneListsTheKnownOnes) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_model_store");
  const std::string path = dir.file("models.sqlite");
  saveIsmTree(path, completeOffice().tree, "test");
  saveIsmTree(path, starGedeck().tree, "test");
  const std::string message = inputErrorOf([&] { loadIsmTree(path, "Spuelkorb_3"); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("Spuelkorb_3"), std::string::npos) << message;
  EXPECT_NE(message.find("office2016, gedeck"), std::string::npos) << message;
}

TEST(ModelStoreErrors, InconsistentModelIsNamed) {
  REQUIRE_RECORDINGS();
  TempDir dir("asr_model_store");
  const std::string path = dir.file("models.sqlite");
  saveIsmTree(path, completeGedeck().tree, "test");
  {
    Database db(path, Database::Mode::kReadWriteCreate);
    db.execute("UPDATE asr_ism_members SET child_ism = 99 WHERE child_ism > 0");
  }
  const std::string message = inputErrorOf([&] { loadIsmTree(path, "gedeck"); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("gedeck"), std::string::npos) << message;
}

}  // namespace
}  // namespace asr_ism_tree::sqlite
