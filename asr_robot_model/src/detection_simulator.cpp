#include "asr_robot_model/detection_simulator.hpp"

#include <algorithm>
#include <cmath>

#include "asr_common/input_error.hpp"

namespace asr_robot_model {
namespace {

void require(bool condition, const std::string& setting, const std::string& rule) {
  if (!condition)
    throw asr_common::InputError("detection settings: " + setting + " " + rule);
}

bool wanted(const std::vector<std::string>& types, const std::string& type) {
  return types.empty() || std::find(types.begin(), types.end(), type) != types.end();
}

}  // namespace

const char* rejectionName(Rejection rejection) {
  switch (rejection) {
    case Rejection::kFrustum:
      return "frustum";
    case Rejection::kNormals:
      return "normals";
    case Rejection::kOccluded:
      return "occluded";
    case Rejection::kMissed:
      return "missed";
  }
  return "unknown";
}

DetectionSimulator::DetectionSimulator(const World& world, const WorldMap& map,
                                       DetectionSettings settings, unsigned seed)
    : world_(world), map_(map), settings_(settings), random_(seed) {
  require(settings_.max_normal_angle > 0.0 && settings_.max_normal_angle <= M_PI,
          "max_normal_angle", "must lie in (0, pi] radians");
  require(std::isfinite(settings_.position_sigma) && settings_.position_sigma >= 0.0,
          "position_sigma", "must be >= 0");
  require(std::isfinite(settings_.angle_sigma) && settings_.angle_sigma >= 0.0, "angle_sigma",
          "must be >= 0");
  require(settings_.miss_probability >= 0.0 && settings_.miss_probability <= 1.0,
          "miss_probability", "must lie in 0..1");
  require(std::isfinite(settings_.seconds_per_type) && settings_.seconds_per_type >= 0.0,
          "seconds_per_type", "must be >= 0");
}

std::optional<Rejection> DetectionSimulator::visibility(const asr_common::Pose& camera,
                                                        const WorldObject& object) const {
  const Eigen::Quaterniond to_camera = camera.orientation.conjugate();
  for (const Eigen::Vector3d& corner : object.box.corners()) {
    if (!settings_.frustum.contains(to_camera * (corner - camera.position)))
      return Rejection::kFrustum;
  }
  if (!object.normals.empty()) {
    const Eigen::Vector3d towards_camera = camera.position - object.box.pose.position;
    const double cos_limit = std::cos(settings_.max_normal_angle);
    const bool facing = std::any_of(
        object.normals.begin(), object.normals.end(), [&](const Eigen::Vector3d& normal) {
          const Eigen::Vector3d n = object.box.pose.orientation * normal;
          // angle < max  <=>  cos(angle) > cos(max); the centre is beyond near > 0 from the eye.
          return n.dot(towards_camera) > cos_limit * towards_camera.norm();
        });
    if (!facing)
      return Rejection::kNormals;
  }
  if (!map_.lineOfSight(camera.position, object.box))
    return Rejection::kOccluded;
  return std::nullopt;
}

asr_common::Pose DetectionSimulator::noisy(const asr_common::Pose& truth) {
  if (settings_.position_sigma == 0.0 && settings_.angle_sigma == 0.0)
    return truth;
  std::normal_distribution<double> position(0.0, settings_.position_sigma);
  std::normal_distribution<double> angle(0.0, settings_.angle_sigma);
  std::normal_distribution<double> axis_component(0.0, 1.0);
  const Eigen::Vector3d shift(position(random_), position(random_), position(random_));
  Eigen::Vector3d axis(axis_component(random_), axis_component(random_), axis_component(random_));
  if (axis.norm() < 1e-12)
    axis = Eigen::Vector3d::UnitZ();
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(angle(random_), axis.normalized()));
  return asr_common::Pose(truth.position + shift, truth.orientation * turn);
}

Detections DetectionSimulator::detect(const asr_common::Pose& camera,
                                      const std::vector<std::string>& types) {
  Detections result;
  std::bernoulli_distribution missed(settings_.miss_probability);
  for (const WorldObject& object : world_.objects) {
    if (!wanted(types, object.key.type))
      continue;
    std::optional<Rejection> why = visibility(camera, object);
    if (!why && missed(random_))
      why = Rejection::kMissed;
    if (why)
      result.rejected.push_back({object.key, *why});
    else
      result.detected.push_back({object.key, noisy(object.box.pose)});
  }
  // Each requested type (every type in the world when none is named) costs its time.
  std::size_t charged = types.size();
  if (types.empty()) {
    std::vector<std::string> all;
    for (const WorldObject& object : world_.objects)
      if (std::find(all.begin(), all.end(), object.key.type) == all.end())
        all.push_back(object.key.type);
    charged = all.size();
  }
  result.seconds = settings_.seconds_per_type * static_cast<double>(charged);
  return result;
}

}  // namespace asr_robot_model
