#pragma once

// The property tests' disturbance of one object's pose: seen badly, by a random turn or shift.

#include <cmath>
#include <random>
#include <string>

#include "asr_common/pose.hpp"
#include "asr_ism/demonstration.hpp"

namespace asr_ism_tree::test_support {

/// A random turn (about a random axis, up to scale x 60 deg) or shift (up to scale x 0.2 m) of
/// `pose`, chosen with equal odds.
inline asr_common::Pose perturbed(const asr_common::Pose& pose, std::mt19937& random,
                                  double scale) {
  constexpr double kDegree = M_PI / 180.0;
  std::normal_distribution<double> normal(0.0, 1.0);
  const Eigen::Vector3d direction =
      Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized();
  asr_common::Pose result = pose;
  if (std::uniform_int_distribution<int>(0, 1)(random) == 0) {
    result.orientation = (pose.orientation *
                          Eigen::Quaterniond(Eigen::AngleAxisd(scale * 60.0 * kDegree, direction)))
                             .normalized();
  } else {
    result.position += scale * 0.2 * direction;
  }
  return result;
}

/// A repeated detection of `estimate`: shifted by `metres` x `gaussian` along each axis, then
/// turned by `radians` x `gaussian` about a random axis (drawn before the angle).
inline asr_common::ObjectEstimate jitteredRepeat(asr_common::ObjectEstimate estimate, double metres,
                                                 double radians,
                                                 std::normal_distribution<double>& gaussian,
                                                 std::mt19937& random) {
  estimate.pose.position +=
      metres * Eigen::Vector3d(gaussian(random), gaussian(random), gaussian(random));
  const Eigen::Vector3d axis(gaussian(random), gaussian(random), gaussian(random));
  estimate.pose.orientation =
      (estimate.pose.orientation *
       Eigen::Quaterniond(Eigen::AngleAxisd(radians * gaussian(random), axis.normalized())))
          .normalized();
  return estimate;
}

/// One case of "seeing an object badly never scores lower than not seeing it": a random recorded
/// set of `demonstration` with one random object perturbed (scale 0.05-1), and the set without it.
struct OneObjectSeenBadly {
  asr_common::Configuration changed;
  asr_common::Configuration removed;
  std::string what;  // which set, object and scale, for a failure's message
};

inline OneObjectSeenBadly oneObjectSeenBadly(const asr_ism::Demonstration& demonstration,
                                             std::mt19937& random) {
  const std::size_t step =
      std::uniform_int_distribution<std::size_t>(0, demonstration.stepCount() - 1)(random);
  const asr_common::Configuration recorded = demonstration.configuration(step);
  const std::size_t object =
      std::uniform_int_distribution<std::size_t>(0, recorded.size() - 1)(random);
  const double scale = std::uniform_real_distribution<double>(0.05, 1.0)(random);
  OneObjectSeenBadly seen{recorded, recorded,
                          "set " + std::to_string(step) + ", " + recorded[object].key.toString() +
                              " perturbed at scale " + std::to_string(scale)};
  seen.removed.erase(seen.removed.begin() + static_cast<std::ptrdiff_t>(object));
  seen.changed[object].pose = perturbed(recorded[object].pose, random, scale);
  return seen;
}

}  // namespace asr_ism_tree::test_support
