#include "asr_nbv/nbv_documents.hpp"

#include <cmath>

#include "asr_common/input_error.hpp"
#include "asr_robot_model/document.hpp"

namespace asr_nbv {
namespace {

using asr_robot_model::Field;

// A coordinate of a predicted pose: null stands for NaN (JSON has none).
double coordinate(const nlohmann::json& node, const Field& field, const char* key) {
  if (!node.contains(key))
    field[key].fail("is missing");
  if (node[key].is_null())
    return std::nan("");
  return field[key].number();
}

asr_common::Pose rawPose(const nlohmann::json& node, const Field& field) {
  const nlohmann::json& p = node["position"];
  const nlohmann::json& o = node["orientation"];
  const Field position = field["position"], orientation = field["orientation"];
  asr_common::Pose pose;
  pose.position = {coordinate(p, position, "x"), coordinate(p, position, "y"),
                   coordinate(p, position, "z")};
  pose.orientation =
      Eigen::Quaterniond(coordinate(o, orientation, "w"), coordinate(o, orientation, "x"),
                         coordinate(o, orientation, "y"), coordinate(o, orientation, "z"));
  return pose;
}

void readPredictions(const nlohmann::json& document, const Field& field,
                     std::vector<PredictedCloud>& clouds) {
  if (!document.is_object() || !document.contains("predictions"))
    field.fail("must be the output of `asr ism predict --json` (no \"predictions\")");
  const nlohmann::json& predictions = document["predictions"];
  const Field list = field["predictions"];
  if (!predictions.is_array())
    list.fail("must be a list");
  for (std::size_t i = 0; i < predictions.size(); ++i) {
    const Field entry = list[i];
    PredictedCloud cloud;
    cloud.key.type = entry["type"].text();
    if (cloud.key.type.empty())
      entry["type"].fail("must not be empty");
    cloud.key.id = entry.has("id") ? entry["id"].text() : "";
    const nlohmann::json& poses = predictions[i]["poses"];
    if (!poses.is_array())
      entry["poses"].fail("must be a list");
    for (std::size_t p = 0; p < poses.size(); ++p) {
      if (!poses[p].is_object() || !poses[p].contains("position") ||
          !poses[p].contains("orientation"))
        entry["poses"][p].fail("must have a position and an orientation");
      cloud.poses.push_back(rawPose(poses[p], entry["poses"][p]));
    }
    clouds.push_back(std::move(cloud));
  }
}

}  // namespace

std::vector<PredictedCloud> readPredictedClouds(const std::string& path) {
  const nlohmann::json document = asr_robot_model::readDocument(path);
  const Field root(document, path, "");
  std::vector<PredictedCloud> clouds;
  if (document.is_array()) {
    for (std::size_t i = 0; i < document.size(); ++i)
      readPredictions(document[i], root[i], clouds);
  } else {
    readPredictions(document, root, clouds);
  }
  return clouds;
}

std::vector<VisitedView> readVisitedViews(const std::string& path) {
  const nlohmann::json document = asr_robot_model::readDocument(path);
  const Field root(document, path, "");
  if (!document.is_array())
    root.fail("must be a list of views");
  std::vector<VisitedView> views;
  for (std::size_t i = 0; i < document.size(); ++i) {
    const Field view = root[i];
    const Field camera = view["camera"];
    VisitedView visited;
    visited.camera =
        asr_common::Pose(camera["position"].position(), camera["orientation"].orientation());
    const Field types = view["types"];
    for (std::size_t t = 0; t < types.size(); ++t)
      visited.types.push_back(types[t].text());
    views.push_back(std::move(visited));
  }
  return views;
}

}  // namespace asr_nbv
