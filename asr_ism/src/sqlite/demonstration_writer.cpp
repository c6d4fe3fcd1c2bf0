#include "asr_ism/sqlite/demonstration_writer.hpp"

#include <algorithm>
#include <cctype>
#include <set>
#include <vector>

#include "asr_ism/common_types.hpp"
#include "asr_ism/sqlite/sqlite_database.hpp"

namespace asr_ism::sqlite {
namespace {

struct TableSchema {
  const char* name;
  // The original ASR tools' definition, used only where the table is missing.
  const char* create;
  std::vector<const char*> columns;
};

const std::vector<TableSchema>& originalTables() {
  static const std::vector<TableSchema> tables = {
      {"recorded_patterns",
       "CREATE TABLE IF NOT EXISTS recorded_patterns (id INTEGER PRIMARY KEY, name TEXT UNIQUE)",
       {"id", "name"}},
      {"recorded_sets",
       "CREATE TABLE IF NOT EXISTS recorded_sets (id INTEGER PRIMARY KEY, patternId INTEGER)",
       {"id", "patternId"}},
      {"recorded_objects",
       "CREATE TABLE IF NOT EXISTS recorded_objects (id INTEGER PRIMARY KEY, type TEXT, observedId "
       "TEXT, "
       "resourcePath TEXT)",
       {"id", "type", "observedId", "resourcePath"}},
      {"recorded_poses",
       "CREATE TABLE IF NOT EXISTS recorded_poses (id INTEGER PRIMARY KEY, objectId INTEGER, setId "
       "INTEGER, "
       "px FLOAT, py FLOAT, pz FLOAT, qw FLOAT, qx FLOAT, qy FLOAT, qz FLOAT)",
       {"id", "objectId", "setId", "px", "py", "pz", "qw", "qx", "qy", "qz"}},
  };
  return tables;
}

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// SQLite column names are case-insensitive, so the comparison is too.
void requireColumns(Database& db, const TableSchema& table) {
  std::set<std::string> present;
  Statement info = db.prepare(std::string("PRAGMA table_info(") + table.name + ")");
  while (info.step())
    present.insert(lowercase(info.columnText(1)));
  std::string missing;
  for (const char* column : table.columns) {
    if (present.count(lowercase(column)) == 0)
      missing += (missing.empty() ? "" : ", ") + std::string(column);
  }
  if (!missing.empty()) {
    throw InputError(db.path() + ": table " + table.name +
                     " does not have the original ASR columns (missing: " + missing + ")");
  }
}

// A configuration checked and canonicalised before anything is written, so an invalid one
// writes nothing.
Configuration validatedConfiguration(const std::string& path, const std::string& scene,
                                     const Configuration& configuration) {
  const std::string what = path + ", scene '" + scene + "'";
  if (scene.empty())
    throw InputError(path + ": cannot record a configuration without a scene name");
  if (configuration.empty())
    throw InputError(what + ": cannot record an empty configuration");
  Configuration checked;
  checked.reserve(configuration.size());
  std::set<ObjectKey> seen;
  for (const ObjectEstimate& estimate : configuration) {
    const std::string object = what + ", object " + estimate.key.toString();
    if (estimate.key.type.empty())
      throw InputError(what + ": an object has an empty type");
    if (!seen.insert(estimate.key).second)
      throw InputError(object + ": appears twice in one configuration");
    // The same check the reader applies, so everything written can be read back.
    checked.push_back(
        {estimate.key, validatedPose(estimate.pose.position, estimate.pose.orientation, object)});
  }
  return checked;
}

// Ids are chosen explicitly rather than left to SQLite, so an existing table whose id column is
// not a rowid alias still gets unique ids.
std::int64_t nextId(Database& db, const char* table) {
  Statement query = db.prepare(std::string("SELECT coalesce(max(id) + 1, 0) FROM ") + table);
  query.step();
  return query.columnInt(0);
}

std::int64_t findOrCreatePattern(Database& db, const std::string& scene) {
  Statement find =
      db.prepare("SELECT id FROM recorded_patterns WHERE name = ? ORDER BY id LIMIT 1");
  find.bind(1, scene);
  if (find.step())
    return find.columnInt(0);
  const std::int64_t id = nextId(db, "recorded_patterns");
  Statement insert = db.prepare("INSERT INTO recorded_patterns (id, name) VALUES (?, ?)");
  insert.bind(1, id).bind(2, scene).execute();
  return id;
}

std::int64_t findOrCreateObject(Database& db, const ObjectKey& key) {
  // A NULL observedId reads as the empty id, so it matches that too.
  Statement find = db.prepare(
      "SELECT id FROM recorded_objects WHERE type = ? AND coalesce(observedId, '') = ? "
      "ORDER BY id LIMIT 1");
  find.bind(1, key.type).bind(2, key.id);
  if (find.step())
    return find.columnInt(0);
  // Another instance of the type already names the mesh the original tools display; reuse it.
  Statement resource = db.prepare(
      "SELECT resourcePath FROM recorded_objects WHERE type = ? AND resourcePath IS NOT NULL "
      "ORDER BY id LIMIT 1");
  resource.bind(1, key.type);
  const std::string resource_path = resource.step() ? resource.columnText(0) : std::string();
  const std::int64_t id = nextId(db, "recorded_objects");
  Statement insert = db.prepare(
      "INSERT INTO recorded_objects (id, type, observedId, resourcePath) VALUES (?, ?, ?, ?)");
  insert.bind(1, id).bind(2, key.type).bind(3, key.id).bind(4, resource_path).execute();
  return id;
}

// Writes one validated configuration inside the caller's transaction.
std::int64_t insertConfiguration(Database& db, const std::string& scene,
                                 const Configuration& configuration) {
  const std::int64_t pattern_id = findOrCreatePattern(db, scene);
  const std::int64_t set_id = nextId(db, "recorded_sets");
  Statement insert_set = db.prepare("INSERT INTO recorded_sets (id, patternId) VALUES (?, ?)");
  insert_set.bind(1, set_id).bind(2, pattern_id).execute();

  Statement insert_pose = db.prepare(
      "INSERT INTO recorded_poses (id, objectId, setId, px, py, pz, qw, qx, qy, qz) "
      "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
  std::int64_t pose_id = nextId(db, "recorded_poses");
  for (const ObjectEstimate& estimate : configuration) {
    const Pose& pose = estimate.pose;
    insert_pose.bind(1, pose_id++)
        .bind(2, findOrCreateObject(db, estimate.key))
        .bind(3, set_id)
        .bind(4, pose.position.x())
        .bind(5, pose.position.y())
        .bind(6, pose.position.z())
        .bind(7, pose.orientation.w())
        .bind(8, pose.orientation.x())
        .bind(9, pose.orientation.y())
        .bind(10, pose.orientation.z())
        .execute();
  }
  return set_id;
}

}  // namespace

DemonstrationWriter::DemonstrationWriter(const std::string& path)
    : db_(std::make_unique<Database>(path, Database::Mode::kReadWriteCreate)) {
  // Check every existing table before creating any, so a file that does not fit stays untouched.
  std::vector<const TableSchema*> missing;
  for (const TableSchema& table : originalTables()) {
    if (db_->hasTable(table.name))
      requireColumns(*db_, table);
    else
      missing.push_back(&table);
  }
  if (missing.empty())
    return;
  Transaction transaction(*db_);
  for (const TableSchema* table : missing)
    db_->execute(table->create);
  transaction.commit();
}

DemonstrationWriter::~DemonstrationWriter() = default;

std::int64_t DemonstrationWriter::appendConfiguration(const std::string& scene,
                                                      const Configuration& configuration) {
  const Configuration checked = validatedConfiguration(db_->path(), scene, configuration);
  Transaction transaction(*db_);
  const std::int64_t set_id = insertConfiguration(*db_, scene, checked);
  transaction.commit();
  return set_id;
}

void appendDemonstration(const std::string& path, const Demonstration& demonstration) {
  if (demonstration.scene().empty())
    throw InputError(path + ": cannot record a demonstration without a scene name");
  // Validate every step first: an invalid step anywhere writes nothing.
  std::vector<Configuration> steps;
  for (std::size_t step = 0; step < demonstration.stepCount(); ++step) {
    const Configuration configuration = demonstration.configuration(step);
    if (!configuration.empty())
      steps.push_back(validatedConfiguration(path, demonstration.scene(), configuration));
  }
  if (steps.empty()) {
    throw InputError(path + ", scene '" + demonstration.scene() +
                     "': the demonstration has no observed object; nothing to record");
  }
  // The writer checks the file and creates missing tables; the steps then go in as one
  // transaction on a connection of our own (the writer's is private and commits per step).
  { DemonstrationWriter prepare_file(path); }
  Database db(path, Database::Mode::kReadWriteCreate);
  Transaction transaction(db);
  for (const Configuration& configuration : steps)
    insertConfiguration(db, demonstration.scene(), configuration);
  transaction.commit();
}

}  // namespace asr_ism::sqlite
