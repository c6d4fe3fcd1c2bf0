#include "asr_ism/sqlite/demonstration_reader.hpp"

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

Demonstration readDemonstration(const std::string& path, const std::string& scene) {
  Database db(path, Database::Mode::kReadOnly);
  requireOriginalSchema(db);

  Statement pattern = db.prepare("SELECT id FROM recorded_patterns WHERE name = ?");
  pattern.bind(1, scene);
  if (!pattern.step()) {
    std::string known;
    for (const auto& name : listRecordedScenes(path))
      known += (known.empty() ? "" : ", ") + name;
    throw InputError(path + ": no demonstration of scene '" + scene +
                     "' (the file has: " + (known.empty() ? "none" : known) + ")");
  }
  const std::int64_t pattern_id = pattern.columnInt(0);

  // Objects in order of first appearance (by pose id), so the order follows the recording.
  Statement objects = db.prepare(
      "SELECT o.id, o.type, o.observedId FROM recorded_objects o "
      "JOIN (SELECT p.objectId AS objectId, min(p.id) AS first FROM recorded_poses p "
      "      JOIN recorded_sets s ON s.id = p.setId WHERE s.patternId = ? GROUP BY p.objectId) f "
      "ON f.objectId = o.id ORDER BY f.first");
  objects.bind(1, pattern_id);
  std::map<std::int64_t, std::size_t> object_index;
  std::vector<ObjectKey> keys;
  while (objects.step()) {
    if (objects.isNull(1) || objects.columnText(1).empty()) {
      throw InputError(path + ", scene '" + scene + "', recorded_objects id " +
                       std::to_string(objects.columnInt(0)) + ": the type is " +
                       (objects.isNull(1) ? "NULL" : "empty"));
    }
    ObjectKey key{objects.columnText(1), objects.columnText(2)};
    const int existing = [&] {
      for (std::size_t i = 0; i < keys.size(); ++i)
        if (keys[i] == key)
          return static_cast<int>(i);
      return -1;
    }();
    // Two rows for one (type, observedId) are the same object recorded twice.
    if (existing >= 0) {
      object_index[objects.columnInt(0)] = static_cast<std::size_t>(existing);
    } else {
      object_index[objects.columnInt(0)] = keys.size();
      keys.push_back(key);
    }
  }
  Demonstration demonstration(scene, keys);

  Statement sets = db.prepare("SELECT id FROM recorded_sets WHERE patternId = ? ORDER BY id");
  sets.bind(1, pattern_id);
  std::map<std::int64_t, std::size_t> step_of_set;
  while (sets.step())
    step_of_set[sets.columnInt(0)] = demonstration.addStep();

  Statement poses = db.prepare(
      "SELECT p.id, p.objectId, p.setId, p.px, p.py, p.pz, p.qw, p.qx, p.qy, p.qz "
      "FROM recorded_poses p JOIN recorded_sets s ON s.id = p.setId "
      "WHERE s.patternId = ? ORDER BY p.id");
  poses.bind(1, pattern_id);
  std::map<std::pair<std::size_t, std::size_t>, std::int64_t> pose_of;  // (step, object) -> id
  while (poses.step()) {
    const std::string row =
        path + ", scene '" + scene + "', recorded_poses id " + std::to_string(poses.columnInt(0));
    double values[7];
    for (int column = 3; column <= 9; ++column)
      values[column - 3] = poses.columnNumber(column, row);
    const Pose pose =
        validatedPose(Eigen::Vector3d(values[0], values[1], values[2]),
                      Eigen::Quaterniond(values[3], values[4], values[5], values[6]), row);
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
  demonstration.validate(path);
  return demonstration;
}

}  // namespace asr_ism::sqlite
