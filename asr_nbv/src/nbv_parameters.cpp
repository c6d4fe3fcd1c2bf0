#include "asr_nbv/nbv_parameters.hpp"

#include <cmath>

#include "asr_common/input_error.hpp"
#include "asr_robot_model/document.hpp"

namespace asr_nbv {
namespace {

using asr_robot_model::Field;

constexpr double kRadiansPerDegree = M_PI / 180.0;

void readNumber(const Field& parent, const char* key, double& value, double scale = 1.0) {
  if (parent.has(key))
    value = parent[key].number() * scale;
}

void require(bool condition, const std::string& field, const std::string& problem) {
  if (!condition)
    throw asr_common::InputError(field + ": " + problem);
}

}  // namespace

void checkNbvParameters(const NbvParameters& p) {
  const RatingWeights& w = p.weights;
  for (const auto& [name, value] : {std::pair{"weights.utility", w.utility},
                                    {"weights.base", w.base},
                                    {"weights.rotation", w.rotation},
                                    {"weights.pan_tilt", w.pan_tilt},
                                    {"weights.recognition", w.recognition}})
    require(std::isfinite(value) && value >= 0.0, name, "must be a number >= 0");
  require(w.sum() > 0.0, "weights", "must not all be 0");
  require(w.utility > 0.0, "weights.utility", "must be > 0 (else nothing is worth seeing)");
  for (const auto& [name, value] :
       {std::pair{"rating_angle", p.rating_angle}, {"update_angle", p.update_angle}})
    require(value > 0.0 && value <= M_PI, name, "must be in (0, 180] degrees");
  require(p.base_distance_sigma > 0.0, "base_distance_sigma", "must be > 0");
  require(p.lattice_radius > 0.0, "lattice_radius", "must be > 0");
  require(p.orientation_step > 0.0 && p.orientation_step <= M_PI / 2, "orientation_step",
          "must be in (0, 90] degrees");
  require(p.max_steps >= 1, "max_steps", "must be >= 1");
  require(p.rating_epsilon >= 0.0, "rating_epsilon", "must be >= 0");
  require(std::isfinite(p.min_utility_for_moving), "min_utility_for_moving", "must be a number");
  require(p.occlusion_resolution > 0.0, "occlusion_resolution", "must be > 0");
}

NbvParameters loadNbvParameters(const std::string& path) {
  const nlohmann::json document = asr_robot_model::readDocument(path);
  const Field root(document, path, "");
  NbvParameters p;
  try {
    if (root.has("frustum")) {
      const Field f = root["frustum"];
      double fovx = p.frustum.fovx(), fovy = p.frustum.fovy();
      double near = p.frustum.near(), far = p.frustum.far();
      readNumber(f, "fovx", fovx, kRadiansPerDegree);
      readNumber(f, "fovy", fovy, kRadiansPerDegree);
      readNumber(f, "near", near);
      readNumber(f, "far", far);
      p.frustum = asr_robot_model::Frustum(fovx, fovy, near, far);
    }
    if (root.has("weights")) {
      const Field w = root["weights"];
      readNumber(w, "utility", p.weights.utility);
      readNumber(w, "base", p.weights.base);
      readNumber(w, "rotation", p.weights.rotation);
      readNumber(w, "pan_tilt", p.weights.pan_tilt);
      readNumber(w, "recognition", p.weights.recognition);
    }
    readNumber(root, "rating_angle", p.rating_angle, kRadiansPerDegree);
    readNumber(root, "update_angle", p.update_angle, kRadiansPerDegree);
    readNumber(root, "base_distance_sigma", p.base_distance_sigma);
    readNumber(root, "lattice_radius", p.lattice_radius);
    readNumber(root, "orientation_step", p.orientation_step, kRadiansPerDegree);
    double max_steps = p.max_steps;
    readNumber(root, "max_steps", max_steps);
    require(max_steps == std::floor(max_steps) && max_steps >= 1 && max_steps <= 1000, "max_steps",
            "must be a whole number in 1..1000");
    p.max_steps = static_cast<int>(max_steps);
    readNumber(root, "rating_epsilon", p.rating_epsilon);
    readNumber(root, "min_utility_for_moving", p.min_utility_for_moving);
    readNumber(root, "occlusion_resolution", p.occlusion_resolution);
    checkNbvParameters(p);
  } catch (const asr_common::InputError& error) {
    const std::string message = error.what();
    if (message.rfind(path, 0) == 0)
      throw;
    throw asr_common::InputError(path + ": " + message);
  }
  return p;
}

std::string defaultNbvParameters() {
  return std::string(ASR_NBV_CONFIG_DIR) + "/next_best_view.yaml";
}

}  // namespace asr_nbv
