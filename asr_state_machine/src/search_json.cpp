#include "asr_state_machine/search_json.hpp"

#include <algorithm>
#include <fstream>

#include "asr_common/input_error.hpp"
#include "asr_robot_model/document.hpp"

namespace asr_state_machine {

namespace {

nlohmann::ordered_json poseJson(const Pose& pose) {
  const Eigen::Vector3d& p = pose.position;
  const Eigen::Quaterniond& q = pose.orientation;
  return {{"position", {{"x", p.x()}, {"y", p.y()}, {"z", p.z()}}},
          {"orientation", {{"x", q.x()}, {"y", q.y()}, {"z", q.z()}, {"w", q.w()}}}};
}

nlohmann::ordered_json robotStateJson(const RobotState& state) {
  return {
      {"x", state.x}, {"y", state.y}, {"yaw", state.yaw}, {"pan", state.pan}, {"tilt", state.tilt}};
}

double median(std::vector<double> values) {
  if (values.empty())
    return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

}  // namespace

nlohmann::ordered_json logEntryJson(const LogEntry& entry) {
  return {{"t", entry.t},
          {"state", entry.state},
          {"event", entry.event},
          {"detail", entry.detail},
          {"compute_ms", entry.compute_seconds * 1000.0}};
}

nlohmann::ordered_json searchResultJson(const SearchResult& result) {
  nlohmann::ordered_json out;
  out["outcome"] = outcomeName(result.outcome);
  out["reason"] = result.reason;
  out["sim_seconds"] = result.sim_seconds;
  out["compute_seconds"] = result.compute_seconds;
  out["decision_compute_ms_median"] = 1000.0 * median(result.decision_compute_seconds);
  out["views"] = result.world.visitedViews().size();
  out["found"] = nlohmann::ordered_json::array();
  for (const FoundObject& found : result.world.foundObjects()) {
    out["found"].push_back({{"type", found.key.type},
                            {"id", found.key.id},
                            {"pose", poseJson(found.pose)},
                            {"found_at_s", found.found_at_s},
                            {"view", found.view}});
  }
  out["scenes"] = nlohmann::ordered_json::array();
  for (const auto& [scene, objects] : result.world.sceneObjects()) {
    nlohmann::ordered_json keys = nlohmann::ordered_json::array();
    for (const ObjectKey& key : objects)
      keys.push_back({{"type", key.type}, {"id", key.id}});
    out["scenes"].push_back(
        {{"scene", scene}, {"confidence", result.world.sceneConfidence(scene)}, {"objects", keys}});
  }
  out["start"] = robotStateJson(result.start);
  out["visited"] = nlohmann::ordered_json::array();
  for (const VisitedView& view : result.world.visitedViews()) {
    out["visited"].push_back({{"camera", poseJson(view.camera)},
                              {"base", robotStateJson(view.base)},
                              {"at_s", view.at_s},
                              {"types", view.types}});
  }
  out["log"] = nlohmann::ordered_json::array();
  for (const LogEntry& entry : result.log)
    out["log"].push_back(logEntryJson(entry));
  return out;
}

namespace {

using asr_robot_model::Field;

Outcome outcomeOf(const Field& field) {
  const std::string name = field.text();
  for (Outcome outcome : {Outcome::kFoundAllObjects, Outcome::kFoundAllRequiredScenes,
                          Outcome::kNowhereLeftToSearch, Outcome::kAborted}) {
    if (name == outcomeName(outcome))
      return outcome;
  }
  field.fail("unknown outcome '" + name + "'");
}

// The pose as written: checked (a unit quaternion) but not normalised again, so that a result
// read back is the result written, to the last bit.
Pose poseOf(const Field& field) {
  const Field orientation = field["orientation"];
  orientation.orientation();
  return Pose(field["position"].position(),
              Eigen::Quaterniond(orientation["w"].number(), orientation["x"].number(),
                                 orientation["y"].number(), orientation["z"].number()));
}

RobotState robotStateOf(const Field& field) {
  RobotState state;
  state.x = field["x"].number();
  state.y = field["y"].number();
  state.yaw = field["yaw"].number();
  state.pan = field["pan"].number();
  state.tilt = field["tilt"].number();
  return state;
}

ObjectKey keyOf(const Field& field) {
  return {field["type"].text(), field["id"].text()};
}

}  // namespace

SearchResult searchResultFromJson(const nlohmann::json& json, const std::string& source) {
  const Field root(json, source, "");
  SearchResult result;
  result.outcome = outcomeOf(root["outcome"]);
  result.reason = root["reason"].text();
  result.sim_seconds = root["sim_seconds"].number();
  result.compute_seconds = root["compute_seconds"].number();
  result.start = robotStateOf(root["start"]);
  const Field scenes = root["scenes"];
  std::map<std::string, std::vector<ObjectKey>> scene_objects;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    std::vector<ObjectKey>& keys = scene_objects[scenes[i]["scene"].text()];
    for (std::size_t k = 0; k < scenes[i]["objects"].size(); ++k)
      keys.push_back(keyOf(scenes[i]["objects"][k]));
  }
  result.world.setSceneObjects(scene_objects);
  for (std::size_t i = 0; i < scenes.size(); ++i)
    result.world.setSceneConfidence(scenes[i]["scene"].text(), scenes[i]["confidence"].number());
  const Field visited = root["visited"];
  for (std::size_t i = 0; i < visited.size(); ++i) {
    VisitedView view{poseOf(visited[i]["camera"]),
                     {},
                     visited[i]["at_s"].number(),
                     robotStateOf(visited[i]["base"])};
    for (std::size_t k = 0; k < visited[i]["types"].size(); ++k)
      view.types.push_back(visited[i]["types"][k].text());
    result.world.addView(view);
  }
  const Field found = root["found"];
  for (std::size_t i = 0; i < found.size(); ++i) {
    const int view = static_cast<int>(found[i]["view"].number());
    if (view < -1 || view >= static_cast<int>(visited.size()))
      found[i]["view"].fail("names no visited view");
    result.world.addEstimate({keyOf(found[i]), poseOf(found[i]["pose"])},
                             found[i]["found_at_s"].number(), view);
  }
  const Field log = root["log"];
  for (std::size_t i = 0; i < log.size(); ++i) {
    result.log.push_back({log[i]["t"].number(), log[i]["state"].text(), log[i]["event"].text(),
                          log[i]["detail"].text(), log[i]["compute_ms"].number() / 1000.0});
  }
  return result;
}

SearchResult readSearchResult(const std::string& path) {
  std::ifstream file(path);
  if (!file)
    throw asr_common::InputError(path + ": cannot read the search result");
  nlohmann::json json = nlohmann::json::parse(file, nullptr, false);
  if (json.is_discarded())
    throw asr_common::InputError(path + ": not a JSON search result");
  return searchResultFromJson(json, path);
}

}  // namespace asr_state_machine
