#include "asr_ism_tree/cli/scene_instance_output.hpp"

#include <cstdio>

namespace asr_ism_tree::cli {

nlohmann::ordered_json poseToJson(const asr_common::Pose& pose) {
  nlohmann::ordered_json json;
  json["position"] = {{"x", pose.position.x()}, {"y", pose.position.y()}, {"z", pose.position.z()}};
  json["orientation"] = {{"x", pose.orientation.x()},
                         {"y", pose.orientation.y()},
                         {"z", pose.orientation.z()},
                         {"w", pose.orientation.w()}};
  return json;
}

nlohmann::ordered_json instanceToJson(const SceneInstance& instance) {
  nlohmann::ordered_json json;
  json["confidence"] = instance.confidence;
  json["object_confidence"] = instance.object_confidence;
  json["ids_ignored"] = instance.ids_ignored;
  json["search_complete"] = instance.search_complete;
  json["pose"] = poseToJson(instance.pose);
  json["objects"] = nlohmann::ordered_json::array();
  for (const InstanceObject& object : instance.objects) {
    json["objects"].push_back({{"type", object.key.type},
                               {"id", object.key.id},
                               {"similarity", object.similarity},
                               {"position_compliance", object.position_compliance},
                               {"orientation_compliance", object.orientation_compliance}});
  }
  json["missing"] = nlohmann::ordered_json::array();
  for (const ObjectKey& key : instance.missing) {
    json["missing"].push_back({{"type", key.type}, {"id", key.id}});
  }
  json["isms"] = nlohmann::ordered_json::array();
  for (const InstanceIsm& ism : instance.isms) {
    json["isms"].push_back({{"name", ism.name}, {"objective", ism.objective}});
  }
  return json;
}

void printInstances(std::ostream& out, const std::vector<SceneInstance>& instances) {
  char line[256];
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const SceneInstance& instance = instances[i];
    const auto& p = instance.pose.position;
    std::snprintf(
        line, sizeof(line),
        "instance %zu: confidence %.3f, object confidence %.3f, at (%.3f, %.3f, %.3f)%s%s\n", i + 1,
        instance.confidence, instance.object_confidence, p.x(), p.y(), p.z(),
        instance.ids_ignored ? ", ids ignored (matched by type)" : "",
        i == 0 && !instance.search_complete
            ? ", a search ran out of its work limits (the best may be higher)"
            : "");
    out << line;
    for (const InstanceObject& object : instance.objects) {
      std::snprintf(
          line, sizeof(line), "  %-32s similarity %.3f  position %.3f  orientation %.3f%s\n",
          object.key.toString().c_str(), object.similarity, object.position_compliance,
          object.orientation_compliance, object.similarity == 0.0 ? "  <- does not fit" : "");
      out << line;
    }
    for (const ObjectKey& key : instance.missing) {
      out << "  " << key.toString() << ": missing\n";
    }
  }
}

}  // namespace asr_ism_tree::cli
