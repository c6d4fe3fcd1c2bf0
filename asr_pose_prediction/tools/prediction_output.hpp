#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "asr_pose_prediction/pose_predictor.hpp"

namespace asr_pose_prediction::tools {

/// What `asr ism predict` found and predicted.
struct PredictionReport {
  std::string scene;
  /// The instances predicted from, best first (one unless --instances K > 1).
  std::vector<SceneInstance> instances;
  std::vector<ObjectPrediction> predictions;
  std::size_t samples = 0;
  double runtime_ms = 0.0;  // prediction only
  /// --instances K > 1: the JSON lists the instances and each prediction's poses_per_instance.
  bool several_instances = false;
  /// --summary: mean position and spread per object instead of (text) or beside (JSON) poses.
  bool summary = false;
};

/// {"scene", "instance_confidence", "runtime_ms", "predictions": [{"type", "id", "path", "poses"}]},
/// with "instances": [{"confidence", "pose"}] and per prediction "poses_per_instance" for several
/// instances, and per prediction "summary" with --summary.
nlohmann::ordered_json predictionReportToJson(const PredictionReport& report);

/// For a person to read: the instance, then per object its path and its poses or their summary.
void printPredictionReport(std::ostream& out, const PredictionReport& report);

}  // namespace asr_pose_prediction::tools
