#pragma once

// A deterministic synthetic demonstration: objects on a ring around the scene's origin, the whole
// arrangement carried across the table from step to step, each object wiggling a little
// (centimetres, degrees) so that every relation has several distinct relative poses.

#include <cmath>
#include <string>
#include <vector>

#include "asr_ism/demonstration.hpp"

namespace asr_ism_tree::synthetic {

using asr_common::Pose;

inline Pose yawPose(double x, double y, double z, double yaw) {
  return Pose(Eigen::Vector3d(x, y, z),
              Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ())));
}

// Where the whole arrangement is at `step`.
inline Pose placement(int step) {
  return yawPose(1.0 + 0.4 * step, 2.0 - 0.25 * step, 0.75, 0.3 * step);
}

// Pose of object `object` of `count` relative to the arrangement at `step`.
inline Pose localPose(int object, int count, int step) {
  const double angle = 2.0 * M_PI * object / count;
  const double wiggle = 0.01 * ((object + step) % 3);
  const double turn = (2.0 * M_PI / 180.0) * ((object * step) % 4);
  return Pose(Eigen::Vector3d((0.3 + wiggle) * std::cos(angle), (0.3 + wiggle) * std::sin(angle),
                              0.04 * object),
              Eigen::Quaterniond(Eigen::AngleAxisd(angle + turn, Eigen::Vector3d::UnitZ())) *
                  Eigen::Quaterniond(Eigen::AngleAxisd(0.1 * object, Eigen::Vector3d::UnitX())));
}

inline asr_ism::Demonstration demonstration(const std::string& scene,
                                            const std::vector<asr_common::ObjectKey>& objects,
                                            int steps = 5) {
  asr_ism::Demonstration result(scene, objects);
  const int count = static_cast<int>(objects.size());
  for (int step = 0; step < steps; ++step) {
    result.addStep();
    for (int object = 0; object < count; ++object)
      result.setPose(step, object,
                     asr_common::compose(placement(step), localPose(object, count, step)));
  }
  return result;
}

}  // namespace asr_ism_tree::synthetic
