#include "prediction_output.hpp"

#include <cmath>
#include <cstdio>

#include "asr_ism_tree/cli/scene_instance_output.hpp"
#include "asr_pose_prediction/pose_cloud_summary.hpp"

namespace asr_pose_prediction::tools {
namespace {

constexpr double kDegreesPerRadian = 180.0 / M_PI;

std::string joined(const std::vector<std::string>& names, const std::string& separator) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i)
    text += (i == 0 ? "" : separator) + names[i];
  return text;
}

nlohmann::ordered_json summaryToJson(const PoseCloudSummary& summary) {
  const Eigen::Vector3d& mean = summary.mean_position;
  return {{"mean_position", {{"x", mean.x()}, {"y", mean.y()}, {"z", mean.z()}}},
          {"position_rms_m", summary.position_rms},
          {"position_max_m", summary.position_max},
          {"angle_rms_deg", summary.angle_rms * kDegreesPerRadian},
          {"angle_max_deg", summary.angle_max * kDegreesPerRadian}};
}

// Why an object is predicted, as the best instance sees it: it has no estimate, or its estimate
// does not fit the instance.
std::string reasonFor(const SceneInstance& instance, const ObjectKey& key) {
  for (const asr_ism_tree::InstanceObject& object : instance.objects) {
    if (object.key == key)
      return object.similarity > 0.0 ? "in the best instance, lacking in another"
                                     : "present but does not fit";
  }
  return "missing";
}

}  // namespace

nlohmann::ordered_json predictionReportToJson(const PredictionReport& report) {
  nlohmann::ordered_json json;
  json["scene"] = report.scene;
  json["instance_confidence"] = report.instances.front().confidence;
  json["runtime_ms"] = report.runtime_ms;
  if (report.several_instances) {
    json["instances"] = nlohmann::ordered_json::array();
    for (const SceneInstance& instance : report.instances) {
      json["instances"].push_back(
          {{"confidence", instance.confidence}, {"pose", asr_ism_tree::cli::poseToJson(instance.pose)}});
    }
  }
  json["predictions"] = nlohmann::ordered_json::array();
  for (const ObjectPrediction& prediction : report.predictions) {
    nlohmann::ordered_json entry;
    entry["type"] = prediction.object.type;
    entry["id"] = prediction.object.id;
    entry["path"] = prediction.path;
    entry["poses"] = nlohmann::ordered_json::array();
    for (const Pose& pose : prediction.poses)
      entry["poses"].push_back(asr_ism_tree::cli::poseToJson(pose));
    if (report.several_instances)
      entry["poses_per_instance"] = prediction.poses_per_instance;
    if (report.summary)
      entry["summary"] = summaryToJson(summarizePoseCloud(prediction.poses));
    json["predictions"].push_back(entry);
  }
  return json;
}

void printPredictionReport(std::ostream& out, const PredictionReport& report) {
  char line[512];
  const SceneInstance& best = report.instances.front();
  const std::string several =
      report.instances.size() > 1
          ? ", predicting from the best " + std::to_string(report.instances.size()) + " instances"
          : "";
  std::snprintf(line, sizeof(line),
                "scene '%s': instance confidence %.3f at (%.3f, %.3f, %.3f)%s; prediction %.3f ms\n",
                report.scene.c_str(), best.confidence, best.pose.position.x(),
                best.pose.position.y(), best.pose.position.z(), several.c_str(),
                report.runtime_ms);
  out << line;
  if (report.predictions.empty()) {
    out << "nothing to predict: the instance contains every object of the scene\n";
    return;
  }
  for (const ObjectPrediction& prediction : report.predictions) {
    out << prediction.object.toString() << " (" << reasonFor(best, prediction.object)
        << "), path " << joined(prediction.path, " > ") << ": " << prediction.poses.size()
        << " poses\n";
    if (report.summary) {
      const PoseCloudSummary summary = summarizePoseCloud(prediction.poses);
      std::snprintf(line, sizeof(line),
                    "  mean position (%.4f, %.4f, %.4f); spread: position rms %.4f m (max %.4f m), "
                    "orientation rms %.2f deg (max %.2f deg)\n",
                    summary.mean_position.x(), summary.mean_position.y(),
                    summary.mean_position.z(), summary.position_rms, summary.position_max,
                    summary.angle_rms * kDegreesPerRadian, summary.angle_max * kDegreesPerRadian);
      out << line;
      continue;
    }
    for (const Pose& pose : prediction.poses) {
      const auto& p = pose.position;
      const auto& q = pose.orientation;
      std::snprintf(line, sizeof(line),
                    "  position (%.4f, %.4f, %.4f)  orientation (%.5f, %.5f, %.5f, %.5f)\n", p.x(),
                    p.y(), p.z(), q.x(), q.y(), q.z(), q.w());
      out << line;
    }
  }
}

}  // namespace asr_pose_prediction::tools
