#include "asr_ism/sqlite/demonstration_reader.hpp"

#include <algorithm>
#include <map>

#include "asr_ism/common_types.hpp"
#include "asr_ism/sqlite/sqlite_database.hpp"

namespace asr_ism::sqlite {
namespace {

void requireOriginalSchema(Database& db) {
  for (const char* table :
       {"recorded_patterns", "recorded_sets", "recorded_objects", "recorded_poses"}) {
    if (!db.hasTable(table)) {
      throw InputError(db.path() + ": not a demonstration file (table " + table + " is missing)");
    }
  }
}

}  // namespace

std::vector<std::string> listRecordedScenes(const std::string& path) {
  Database db(path, Database::Mode::kReadOnly);
  requireOriginalSchema(db);
  std::vector<std::string> scenes;
  Statement query = db.prepare("SELECT name FROM recorded_patterns ORDER BY id");
  while (query.step())
    scenes.push_back(query.columnText(0));
  return scenes;
}

namespace {

// The id of the scene's row in recorded_patterns; throws naming the scenes the file has.
std::int64_t patternId(Database& db, const std::string& path, const std::string& scene) {
  Statement pattern = db.prepare("SELECT id FROM recorded_patterns WHERE name = ?");
  pattern.bind(1, scene);
  if (!pattern.step()) {
    std::string known;
    for (const auto& name : listRecordedScenes(path))
      known += (known.empty() ? "" : ", ") + name;
    throw InputError(path + ": no demonstration of scene '" + scene +
                     "' (the file has: " + (known.empty() ? "none" : known) + ")");
  }
  return pattern.columnInt(0);
}

// The scene's objects in order of first appearance (by pose id), so the order follows the
// recording, and the index of each recorded_objects id among them: two rows for one
// (type, observedId) are the same object recorded twice. Throws for a NULL or empty type.
std::vector<ObjectKey> sceneObjects(Database& db, std::int64_t pattern_id, const std::string& where,
                                    std::map<std::int64_t, std::size_t>& object_index) {
  Statement objects = db.prepare(
      "SELECT o.id, o.type, o.observedId FROM recorded_objects o "
      "JOIN (SELECT p.objectId AS objectId, min(p.id) AS first FROM recorded_poses p "
      "      JOIN recorded_sets s ON s.id = p.setId WHERE s.patternId = ? GROUP BY p.objectId) f "
      "ON f.objectId = o.id ORDER BY f.first");
  objects.bind(1, pattern_id);
  std::vector<ObjectKey> keys;
  while (objects.step()) {
    if (objects.isNull(1) || objects.columnText(1).empty()) {
      throw InputError(where + ", recorded_objects id " + std::to_string(objects.columnInt(0)) +
                       ": the type is " + (objects.isNull(1) ? "NULL" : "empty"));
    }
    const ObjectKey key{objects.columnText(1), objects.columnText(2)};
    const auto existing = std::find(keys.begin(), keys.end(), key);
    object_index[objects.columnInt(0)] = static_cast<std::size_t>(existing - keys.begin());
    if (existing == keys.end())
      keys.push_back(key);
  }
  return keys;
}

// The pose of the current row of `poses` (columns 3 to 9), checked.
Pose rowPose(Statement& poses, const std::string& row) {
  double values[7];
  for (int column = 3; column <= 9; ++column)
    values[column - 3] = poses.columnNumber(column, row);
  return validatedPose(Eigen::Vector3d(values[0], values[1], values[2]),
                       Eigen::Quaterniond(values[3], values[4], values[5], values[6]), row);
}

// Every pose of the scene into its step and object; throws for a pose of an unknown object or a
// second pose of one object in one set.
void readPoses(Database& db, std::int64_t pattern_id, const std::string& where,
               const std::map<std::int64_t, std::size_t>& object_index,
               const std::map<std::int64_t, std::size_t>& step_of_set,
               Demonstration& demonstration) {
  Statement poses = db.prepare(
      "SELECT p.id, p.objectId, p.setId, p.px, p.py, p.pz, p.qw, p.qx, p.qy, p.qz "
      "FROM recorded_poses p JOIN recorded_sets s ON s.id = p.setId "
      "WHERE s.patternId = ? ORDER BY p.id");
  poses.bind(1, pattern_id);
  std::map<std::pair<std::size_t, std::size_t>, std::int64_t> pose_of;  // (step, object) -> id
  while (poses.step()) {
    const std::string row = where + ", recorded_poses id " + std::to_string(poses.columnInt(0));
    const Pose pose = rowPose(poses, row);
    const auto object = object_index.find(poses.columnInt(1));
    if (object == object_index.end()) {
      throw InputError(row + ": object id " + std::to_string(poses.columnInt(1)) +
                       " is not in recorded_objects");
    }
    const std::size_t step = step_of_set.at(poses.columnInt(2));
    const auto [earlier, first] =
        pose_of.emplace(std::make_pair(step, object->second), poses.columnInt(0));
    if (!first) {
      throw InputError(row + ": a second pose of " +
                       demonstration.objects()[object->second].toString() +
                       " in recorded_sets id " + std::to_string(poses.columnInt(2)) +
                       " (the first is recorded_poses id " + std::to_string(earlier->second) +
                       "); one object has one pose per set");
    }
    demonstration.setPose(step, object->second, pose);
  }
}

}  // namespace

Demonstration readDemonstration(const std::string& path, const std::string& scene) {
  Database db(path, Database::Mode::kReadOnly);
  requireOriginalSchema(db);
  const std::int64_t pattern_id = patternId(db, path, scene);
  const std::string where = path + ", scene '" + scene + "'";
  std::map<std::int64_t, std::size_t> object_index;
  Demonstration demonstration(scene, sceneObjects(db, pattern_id, where, object_index));

  Statement sets = db.prepare("SELECT id FROM recorded_sets WHERE patternId = ? ORDER BY id");
  sets.bind(1, pattern_id);
  std::map<std::int64_t, std::size_t> step_of_set;
  while (sets.step())
    step_of_set[sets.columnInt(0)] = demonstration.addStep();
  readPoses(db, pattern_id, where, object_index, step_of_set, demonstration);
  demonstration.validate(path);
  return demonstration;
}

}  // namespace asr_ism::sqlite
