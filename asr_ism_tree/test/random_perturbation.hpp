#pragma once

// The property tests' disturbance of one object's pose: seen badly, by a random turn or shift.

#include <cmath>
#include <random>

#include "asr_common/pose.hpp"

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

}  // namespace asr_ism_tree::test_support
