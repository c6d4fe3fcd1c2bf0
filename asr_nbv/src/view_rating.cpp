#include "asr_nbv/view_rating.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace asr_nbv {
namespace {

// cos(angle), remembered for the last angle asked on this thread: the thresholds are the same
// for millions of calls.
double cosineOf(double angle) {
  thread_local double last_angle = 0.0, last_cosine = 1.0;
  if (angle != last_angle) {
    last_angle = angle;
    last_cosine = std::cos(angle);
  }
  return last_cosine;
}

double angleBetweenVectors(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

double jointRange(const asr_robot_model::RevoluteJoint& joint) {
  return joint.upper - joint.lower;
}

}  // namespace

double raisedCosine(double d, double threshold) {
  if (!(d < threshold))
    return 0.0;
  return 0.5 + 0.5 * std::cos(M_PI * d / threshold);
}

bool inFrustum(const asr_common::Pose& camera, const Eigen::Vector3d& point,
               const asr_robot_model::Frustum& frustum) {
  return frustum.contains(camera.orientation.conjugate() * (point - camera.position));
}

double orientationUtility(const Hypothesis& hypothesis, const Eigen::Vector3d& camera_position,
                          double rating_angle) {
  if (hypothesis.normals.empty())
    return hypothesis.active[0] ? 1.0 : 0.0;
  const Eigen::Vector3d to_camera = camera_position - hypothesis.box.pose.position;
  // Normals at least rating_angle away contribute nothing: skip them without an arc function.
  const double cosine_limit = cosineOf(rating_angle) * to_camera.norm();
  double best = 0.0;
  for (std::size_t n = 0; n < hypothesis.normals.size(); ++n) {
    if (hypothesis.active[n] && to_camera.dot(hypothesis.normals[n]) > cosine_limit)
      best = std::max(
          best, raisedCosine(angleBetweenVectors(to_camera, hypothesis.normals[n]), rating_angle));
  }
  return best;
}

double sideProximity(const Eigen::Vector3d& axis, const Eigen::Vector3d& offset,
                     const asr_robot_model::Frustum& frustum) {
  const double side_angle = std::min(frustum.fovx(), frustum.fovy()) / 2.0;
  const double depth = axis.dot(offset);
  const double distance = offset.norm();
  if (depth <= cosineOf(side_angle) * distance)
    return 0.0;
  const double middle = (frustum.near() + frustum.far()) / 2.0;
  const double proximity =
      raisedCosine(std::abs(depth - middle), (frustum.far() - frustum.near()) / 2.0);
  if (proximity == 0.0)
    return 0.0;
  // Within the side angle (< 90 deg) the arc cosine is accurate enough and cheaper than atan2.
  return proximity * raisedCosine(std::acos(std::min(1.0, depth / distance)), side_angle);
}

double hypothesisUtility(const asr_common::Pose& camera, const Hypothesis& hypothesis,
                         const NbvParameters& parameters) {
  const Eigen::Vector3d& point = hypothesis.box.pose.position;
  if (!hypothesis.counts())
    return 0.0;
  // The side test first: it rejects most hypotheses more cheaply than the frustum test.
  const double terms = sideProximity(camera.orientation * Eigen::Vector3d::UnitZ(),
                                     point - camera.position, parameters.frustum);
  if (terms == 0.0 || !inFrustum(camera, point, parameters.frustum))
    return 0.0;
  return orientationUtility(hypothesis, camera.position, parameters.rating_angle) * terms;
}

ViewUtility viewUtility(const asr_common::Pose& camera, const HypothesisSet& hypotheses,
                        const NbvParameters& parameters, const asr_robot_model::WorldMap* map) {
  ViewUtility utility;
  utility.per_type.assign(hypotheses.types().size(), 0.0);
  for (const Hypothesis& hypothesis : hypotheses.hypotheses()) {
    const double u = hypothesisUtility(camera, hypothesis, parameters);
    if (u > 0.0 && (map == nullptr || map->lineOfSight(camera.position, hypothesis.box)))
      utility.per_type[hypothesis.type] += u;
  }
  utility.total = std::accumulate(utility.per_type.begin(), utility.per_type.end(), 0.0);
  return utility;
}

InverseCosts inverseCosts(const asr_robot_model::Motion& motion,
                          const asr_robot_model::RobotState& from,
                          const asr_robot_model::RobotState& to,
                          const asr_robot_model::RobotDescription& robot,
                          std::size_t searched_types, std::size_t type_count,
                          const NbvParameters& parameters) {
  InverseCosts costs;
  const double sigma = parameters.base_distance_sigma;
  costs.base = std::exp(-motion.path_length * motion.path_length / (2.0 * sigma * sigma));
  costs.rotation = std::max(0.0, 1.0 - motion.turning / (2.0 * M_PI));
  const double pan_range = jointRange(robot.pan), tilt_range = jointRange(robot.tilt);
  const double pan = pan_range > 0.0 ? 1.0 - std::abs(to.pan - from.pan) / pan_range : 1.0;
  const double tilt = tilt_range > 0.0 ? 1.0 - std::abs(to.tilt - from.tilt) / tilt_range : 1.0;
  costs.pan_tilt = std::clamp(std::min(pan, tilt), 0.0, 1.0);
  costs.recognition = type_count > 0 ? 1.0 - static_cast<double>(searched_types) / type_count : 0.0;
  return costs;
}

double rating(double utility, double utility_max, const InverseCosts& costs,
              const RatingWeights& weights) {
  const double normalised = utility_max > 0.0 ? utility / utility_max : 0.0;
  return (weights.utility * normalised + weights.base * costs.base +
          weights.rotation * costs.rotation + weights.pan_tilt * costs.pan_tilt +
          weights.recognition * costs.recognition) /
         weights.sum();
}

TypeChoice bestTypeSubset(const std::vector<double>& per_type_utility, double utility_max,
                          std::size_t type_count, const RatingWeights& weights) {
  std::vector<int> order;
  for (std::size_t t = 0; t < per_type_utility.size(); ++t) {
    if (per_type_utility[t] > 0.0)
      order.push_back(static_cast<int>(t));
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return per_type_utility[a] > per_type_utility[b]; });
  TypeChoice choice;
  if (order.empty() || utility_max <= 0.0 || type_count == 0)
    return choice;
  double best_value = -1.0, prefix = 0.0;
  std::size_t best_k = 0;
  for (std::size_t k = 1; k <= order.size(); ++k) {
    prefix += per_type_utility[order[k - 1]];
    const double value = weights.utility * prefix / utility_max +
                         weights.recognition * (1.0 - static_cast<double>(k) / type_count);
    if (value > best_value) {
      best_value = value;
      best_k = k;
      choice.utility = prefix;
    }
  }
  choice.types.assign(order.begin(), order.begin() + static_cast<long>(best_k));
  return choice;
}

std::size_t updateAfterView(HypothesisSet& hypotheses, const asr_common::Pose& camera,
                            const std::vector<std::string>& types, const NbvParameters& parameters,
                            const asr_robot_model::WorldMap* map) {
  std::vector<char> searched(hypotheses.types().size(), 0);
  for (const std::string& type : types) {
    const int index = hypotheses.typeIndex(type);
    if (index >= 0)
      searched[index] = 1;
  }
  std::size_t deactivated = 0;
  std::vector<std::size_t> seen;
  for (Hypothesis& hypothesis : hypotheses.hypotheses()) {
    if (!hypothesis.counts() || !searched[hypothesis.type] ||
        !inFrustum(camera, hypothesis.box.pose.position, parameters.frustum))
      continue;
    const Eigen::Vector3d to_camera = camera.position - hypothesis.box.pose.position;
    seen.clear();
    for (std::size_t n = 0; n < hypothesis.active.size(); ++n) {
      if (hypothesis.active[n] &&
          (hypothesis.normals.empty() ||
           angleBetweenVectors(to_camera, hypothesis.normals[n]) < parameters.update_angle))
        seen.push_back(n);
    }
    // The line of sight last: it is the expensive test.
    if (seen.empty() || (map != nullptr && !map->lineOfSight(camera.position, hypothesis.box)))
      continue;
    for (std::size_t n : seen)
      hypothesis.active[n] = 0;
    hypothesis.active_count -= static_cast<int>(seen.size());
    deactivated += seen.size();
  }
  return deactivated;
}

}  // namespace asr_nbv
