#include "asr_ism_tree/sqlite/model_store.hpp"

#include <cmath>
#include <ctime>

#include "asr_common/input_error.hpp"
#include "asr_ism/input_limits.hpp"
#include "asr_ism/sqlite/sqlite_database.hpp"

namespace asr_ism_tree::sqlite {

using asr_common::InputError;
using asr_ism::sqlite::Database;
using asr_ism::sqlite::Statement;
using asr_ism::sqlite::Transaction;

namespace {

constexpr const char* kSchemaName = "asr_ism_tree_models";

// Only tables with the asr_ism_ prefix are ours; nothing else in a file is ever touched.
const char* const kCreateTables[] = {
    "CREATE TABLE IF NOT EXISTS asr_ism_schema ("
    " name TEXT PRIMARY KEY, version INTEGER NOT NULL)",
    "CREATE TABLE IF NOT EXISTS asr_ism_trees ("
    " id INTEGER PRIMARY KEY, scene TEXT NOT NULL UNIQUE, bin_size REAL NOT NULL,"
    " max_angle_deviation REAL NOT NULL, source TEXT NOT NULL, created TEXT NOT NULL)",
    "CREATE TABLE IF NOT EXISTS asr_ism_objects ("
    " tree_id INTEGER NOT NULL, position INTEGER NOT NULL, type TEXT NOT NULL,"
    " observed_id TEXT NOT NULL, PRIMARY KEY (tree_id, position)) WITHOUT ROWID",
    "CREATE TABLE IF NOT EXISTS asr_ism_relations ("
    " tree_id INTEGER NOT NULL, object_a INTEGER NOT NULL, object_b INTEGER NOT NULL,"
    " PRIMARY KEY (tree_id, object_a, object_b)) WITHOUT ROWID",
    "CREATE TABLE IF NOT EXISTS asr_ism_isms ("
    " tree_id INTEGER NOT NULL, position INTEGER NOT NULL, name TEXT NOT NULL,"
    " parent INTEGER NOT NULL, level INTEGER NOT NULL, reference_type TEXT NOT NULL,"
    " reference_id TEXT NOT NULL, PRIMARY KEY (tree_id, position)) WITHOUT ROWID",
    "CREATE TABLE IF NOT EXISTS asr_ism_members ("
    " tree_id INTEGER NOT NULL, ism INTEGER NOT NULL, position INTEGER NOT NULL,"
    " type TEXT NOT NULL, observed_id TEXT NOT NULL, child_ism INTEGER NOT NULL,"
    " PRIMARY KEY (tree_id, ism, position)) WITHOUT ROWID",
    "CREATE TABLE IF NOT EXISTS asr_ism_relative_poses ("
    " tree_id INTEGER NOT NULL, ism INTEGER NOT NULL, member INTEGER NOT NULL,"
    " position INTEGER NOT NULL, px REAL NOT NULL, py REAL NOT NULL, pz REAL NOT NULL,"
    " qw REAL NOT NULL, qx REAL NOT NULL, qy REAL NOT NULL, qz REAL NOT NULL,"
    " step_count INTEGER NOT NULL, PRIMARY KEY (tree_id, ism, member, position)) WITHOUT ROWID",
};

const char* const kTreeTables[] = {"asr_ism_objects", "asr_ism_relations", "asr_ism_isms",
                                   "asr_ism_members", "asr_ism_relative_poses"};

// Throws unless the file's model tables are of a version this code understands. Returns false if
// the file has no model tables at all.
bool checkSchemaVersion(Database& db) {
  if (!db.hasTable("asr_ism_schema")) {
    if (db.hasTable("asr_ism_trees")) {
      throw InputError(db.path() +
                       ": model tables without a schema version; not written by this "
                       "suite");
    }
    return false;
  }
  Statement version = db.prepare("SELECT version FROM asr_ism_schema WHERE name = ?");
  version.bind(1, std::string(kSchemaName));
  if (!version.step()) {
    throw InputError(db.path() + ": asr_ism_schema has no entry for " + kSchemaName);
  }
  if (version.columnInt(0) > kModelSchemaVersion) {
    throw InputError(db.path() + ": models were written with schema version " +
                     std::to_string(version.columnInt(0)) + "; this build reads up to " +
                     std::to_string(kModelSchemaVersion) + ". Update the suite.");
  }
  return true;
}

std::string utcTimestamp() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);  // std::gmtime shares a static buffer between threads
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

// The scene's row in asr_ism_trees, new or updated; its id. A previous model of the scene loses
// its rows in our tables only, and keeps its tree id, so listModelScenes keeps listing scenes in
// the order they were first stored.
std::int64_t treeRow(Database& db, const IsmTree& tree, const std::string& source) {
  Statement previous = db.prepare("SELECT id FROM asr_ism_trees WHERE scene = ?");
  previous.bind(1, tree.scene);
  if (!previous.step()) {
    Statement insert_tree = db.prepare(
        "INSERT INTO asr_ism_trees (scene, bin_size, max_angle_deviation, source, created) "
        "VALUES (?, ?, ?, ?, ?)");
    insert_tree.bind(1, tree.scene)
        .bind(2, tree.parameters.bin_size)
        .bind(3, tree.parameters.max_angle_deviation)
        .bind(4, source)
        .bind(5, utcTimestamp())
        .execute();
    return db.lastInsertId();
  }
  const std::int64_t tree_id = previous.columnInt(0);
  previous.reset();  // finish the read before changing the table it reads
  for (const char* table : kTreeTables) {
    Statement remove = db.prepare(std::string("DELETE FROM ") + table + " WHERE tree_id = ?");
    remove.bind(1, tree_id).execute();
  }
  Statement update_tree = db.prepare(
      "UPDATE asr_ism_trees SET bin_size = ?, max_angle_deviation = ?, source = ?, created = ? "
      "WHERE id = ?");
  update_tree.bind(1, tree.parameters.bin_size)
      .bind(2, tree.parameters.max_angle_deviation)
      .bind(3, source)
      .bind(4, utcTimestamp())
      .bind(5, tree_id)
      .execute();
  return tree_id;
}

void saveTopology(Database& db, std::int64_t tree_id, const IsmTree& tree) {
  Statement insert_object = db.prepare(
      "INSERT INTO asr_ism_objects (tree_id, position, type, observed_id) VALUES (?, ?, ?, ?)");
  for (std::size_t i = 0; i < tree.objects().size(); ++i) {
    insert_object.bind(1, tree_id)
        .bind(2, static_cast<std::int64_t>(i))
        .bind(3, tree.objects()[i].type)
        .bind(4, tree.objects()[i].id)
        .execute();
  }
  Statement insert_relation =
      db.prepare("INSERT INTO asr_ism_relations (tree_id, object_a, object_b) VALUES (?, ?, ?)");
  for (const auto& [a, b] : tree.topology.relations())
    insert_relation.bind(1, tree_id).bind(2, a).bind(3, b).execute();
}

void saveRelativePoses(Statement& insert_pose, std::int64_t tree_id, std::size_t ism,
                       std::size_t member_index, const asr_ism::IsmMember& member) {
  for (std::size_t r = 0; r < member.relative_poses.size(); ++r) {
    const auto& pose = member.relative_poses[r].reference_in_member;
    insert_pose.bind(1, tree_id)
        .bind(2, static_cast<std::int64_t>(ism))
        .bind(3, static_cast<std::int64_t>(member_index))
        .bind(4, static_cast<std::int64_t>(r))
        .bind(5, pose.position.x())
        .bind(6, pose.position.y())
        .bind(7, pose.position.z())
        .bind(8, pose.orientation.w())
        .bind(9, pose.orientation.x())
        .bind(10, pose.orientation.y())
        .bind(11, pose.orientation.z())
        .bind(12, static_cast<std::int64_t>(member.relative_poses[r].step_count))
        .execute();
  }
}

void saveIsms(Database& db, std::int64_t tree_id, const IsmTree& tree) {
  Statement insert_ism = db.prepare(
      "INSERT INTO asr_ism_isms (tree_id, position, name, parent, level, reference_type, "
      "reference_id) VALUES (?, ?, ?, ?, ?, ?, ?)");
  Statement insert_member = db.prepare(
      "INSERT INTO asr_ism_members (tree_id, ism, position, type, observed_id, child_ism) "
      "VALUES (?, ?, ?, ?, ?, ?)");
  Statement insert_pose = db.prepare(
      "INSERT INTO asr_ism_relative_poses (tree_id, ism, member, position, px, py, pz, qw, qx, "
      "qy, qz, step_count) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  for (std::size_t i = 0; i < tree.isms.size(); ++i) {
    const auto& ism = tree.isms[i];
    insert_ism.bind(1, tree_id)
        .bind(2, static_cast<std::int64_t>(i))
        .bind(3, ism.name)
        .bind(4, tree.parent[i])
        .bind(5, tree.level[i])
        .bind(6, ism.reference.type)
        .bind(7, ism.reference.id)
        .execute();
    for (std::size_t m = 0; m < ism.members.size(); ++m) {
      const auto& member = ism.members[m];
      insert_member.bind(1, tree_id)
          .bind(2, static_cast<std::int64_t>(i))
          .bind(3, static_cast<std::int64_t>(m))
          .bind(4, member.object.type)
          .bind(5, member.object.id)
          .bind(6, member.child_ism)
          .execute();
      saveRelativePoses(insert_pose, tree_id, i, m, member);
    }
  }
}

}  // namespace

void saveIsmTree(const std::string& path, const IsmTree& tree, const std::string& source) {
  tree.validate("model to save");
  Database db(path, Database::Mode::kReadWriteCreate);
  checkSchemaVersion(db);
  Transaction transaction(db);
  for (const char* statement : kCreateTables)
    db.execute(statement);
  Statement version =
      db.prepare("INSERT OR IGNORE INTO asr_ism_schema (name, version) VALUES (?, ?)");
  version.bind(1, std::string(kSchemaName)).bind(2, kModelSchemaVersion).execute();
  const std::int64_t tree_id = treeRow(db, tree, source);
  saveTopology(db, tree_id, tree);
  saveIsms(db, tree_id, tree);
  transaction.commit();
}

std::vector<std::string> listModelScenes(const std::string& path) {
  Database db(path, Database::Mode::kReadOnly);
  std::vector<std::string> scenes;
  if (!checkSchemaVersion(db))
    return scenes;
  Statement query = db.prepare("SELECT scene FROM asr_ism_trees ORDER BY id");
  while (query.step())
    scenes.push_back(query.columnText(0));
  return scenes;
}

namespace {

RelationTopology loadTopology(Database& db, std::int64_t tree_id, const std::string& named) {
  std::vector<ObjectKey> objects;
  Statement object_rows = db.prepare(
      "SELECT type, observed_id FROM asr_ism_objects WHERE tree_id = ? ORDER BY position");
  object_rows.bind(1, tree_id);
  while (object_rows.step())
    objects.push_back({object_rows.columnText(0), object_rows.columnText(1)});
  RelationTopology topology(objects);
  Statement relation_rows =
      db.prepare("SELECT object_a, object_b FROM asr_ism_relations WHERE tree_id = ?");
  relation_rows.bind(1, tree_id);
  while (relation_rows.step()) {
    const auto a = relation_rows.columnInt(0), b = relation_rows.columnInt(1);
    if (a < 0 || b < 0 || a == b || a >= static_cast<std::int64_t>(objects.size()) ||
        b >= static_cast<std::int64_t>(objects.size())) {
      throw InputError(named + ": a stored relation names no object");
    }
    topology.addRelation(static_cast<std::size_t>(a), static_cast<std::size_t>(b));
  }
  return topology;
}

void loadIsms(Database& db, std::int64_t tree_id, const std::string& named, IsmTree& tree) {
  Statement ism_rows = db.prepare(
      "SELECT name, parent, level, reference_type, reference_id FROM asr_ism_isms "
      "WHERE tree_id = ? ORDER BY position");
  ism_rows.bind(1, tree_id);
  while (ism_rows.step()) {
    asr_ism::Ism ism;
    ism.name = ism_rows.columnText(0);
    ism.reference = {ism_rows.columnText(3), ism_rows.columnText(4)};
    tree.isms.push_back(std::move(ism));
    tree.parent.push_back(static_cast<int>(ism_rows.columnInt(1)));
    tree.level.push_back(static_cast<int>(ism_rows.columnInt(2)));
  }
  const auto ism_index = [&](std::int64_t value) {
    if (value < 0 || value >= static_cast<std::int64_t>(tree.isms.size()))
      throw InputError(named + ": a stored member names no ISM");
    return static_cast<std::size_t>(value);
  };
  Statement member_rows = db.prepare(
      "SELECT ism, type, observed_id, child_ism FROM asr_ism_members WHERE tree_id = ? "
      "ORDER BY ism, position");
  member_rows.bind(1, tree_id);
  while (member_rows.step()) {
    asr_ism::IsmMember member;
    member.object = {member_rows.columnText(1), member_rows.columnText(2)};
    member.child_ism = static_cast<int>(member_rows.columnInt(3));
    tree.isms[ism_index(member_rows.columnInt(0))].members.push_back(std::move(member));
  }
}

// The stored relative poses of a tree, checked like a demonstration's poses.
void loadRelativePoses(Database& db, std::int64_t tree_id, const std::string& named,
                       IsmTree& tree) {
  const auto ism_index = [&](std::int64_t value) {
    if (value < 0 || value >= static_cast<std::int64_t>(tree.isms.size()))
      throw InputError(named + ": a stored relative pose names no ISM");
    return static_cast<std::size_t>(value);
  };
  Statement pose_rows = db.prepare(
      "SELECT ism, member, px, py, pz, qw, qx, qy, qz, step_count, position "
      "FROM asr_ism_relative_poses WHERE tree_id = ? ORDER BY ism, member, position");
  pose_rows.bind(1, tree_id);
  while (pose_rows.step()) {
    auto& members = tree.isms[ism_index(pose_rows.columnInt(0))].members;
    const auto m = pose_rows.columnInt(1);
    const std::string row = named + ", asr_ism_relative_poses (ism " +
                            std::to_string(pose_rows.columnInt(0)) + ", member " +
                            std::to_string(m) + ", position " +
                            std::to_string(pose_rows.columnInt(10)) + ")";
    if (m < 0 || m >= static_cast<std::int64_t>(members.size()))
      throw InputError(row + ": names no member");
    double values[7];
    for (int column = 2; column <= 8; ++column)
      values[column - 2] = pose_rows.columnNumber(column, row);
    const double step_count = pose_rows.columnNumber(9, row);
    if (!(step_count >= 1 && step_count <= 4294967295.0 && step_count == std::floor(step_count)))
      throw InputError(row + ": step_count must be a whole number >= 1");
    asr_common::Pose pose;
    pose.position = Eigen::Vector3d(values[0], values[1], values[2]);
    pose.orientation = Eigen::Quaterniond(values[3], values[4], values[5], values[6]);
    // Checked, but kept bit for bit as stored: a loaded tree recognises exactly like the learned.
    asr_common::validatedPose(pose.position, pose.orientation, row, 1e-9);
    members[m].relative_poses.push_back({pose, static_cast<std::uint32_t>(step_count)});
  }
}

}  // namespace

IsmTree loadIsmTree(const std::string& path, const std::string& scene) {
  Database db(path, Database::Mode::kReadOnly);
  if (!checkSchemaVersion(db)) {
    throw InputError(path + ": contains no ISM tree model (learn one with `asr ism learn`)");
  }
  Statement tree_row =
      db.prepare("SELECT id, bin_size, max_angle_deviation FROM asr_ism_trees WHERE scene = ?");
  tree_row.bind(1, scene);
  if (!tree_row.step()) {
    std::string known;
    for (const auto& name : listModelScenes(path))
      known += (known.empty() ? "" : ", ") + name;
    throw InputError(path + ": no model of scene '" + scene +
                     "' (the file has: " + (known.empty() ? "none" : known) + ")");
  }
  const std::string named = path + ", scene '" + scene + "'";
  const std::int64_t tree_id = tree_row.columnInt(0);
  IsmTree tree;
  tree.scene = scene;
  tree.parameters.bin_size = tree_row.columnNumber(1, named + ", asr_ism_trees");
  tree.parameters.max_angle_deviation = tree_row.columnNumber(2, named + ", asr_ism_trees");
  asr_ism::checkRecognitionParameters(tree.parameters, named + ", asr_ism_trees");

  tree.topology = loadTopology(db, tree_id, named);
  loadIsms(db, tree_id, named, tree);
  loadRelativePoses(db, tree_id, named, tree);
  tree.validate(path);
  return tree;
}

}  // namespace asr_ism_tree::sqlite
