#include "asr_state_machine/search_json.hpp"

#include <algorithm>

namespace asr_state_machine {

namespace {

nlohmann::ordered_json poseJson(const Pose& pose) {
  const Eigen::Vector3d& p = pose.position;
  const Eigen::Quaterniond& q = pose.orientation;
  return {{"position", {{"x", p.x()}, {"y", p.y()}, {"z", p.z()}}},
          {"orientation", {{"x", q.x()}, {"y", q.y()}, {"z", q.z()}, {"w", q.w()}}}};
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
    out["scenes"].push_back(
        {{"scene", scene}, {"confidence", result.world.sceneConfidence(scene)}});
  }
  out["log"] = nlohmann::ordered_json::array();
  for (const LogEntry& entry : result.log)
    out["log"].push_back(logEntryJson(entry));
  return out;
}

}  // namespace asr_state_machine
