#include "asr_robot_model/frustum.hpp"

#include <cmath>
#include <string>

#include "asr_common/input_error.hpp"

namespace asr_robot_model {
namespace {

void require(bool condition, const std::string& field, const std::string& rule) {
  if (!condition)
    throw asr_common::InputError("frustum: " + field + " " + rule);
}

}  // namespace

Frustum::Frustum(double fovx, double fovy, double near, double far)
    : fovx_(fovx), fovy_(fovy), near_(near), far_(far) {
  require(fovx > 0.0 && fovx < M_PI, "fovx", "must lie in (0, pi) radians");
  require(fovy > 0.0 && fovy < M_PI, "fovy", "must lie in (0, pi) radians");
  require(std::isfinite(near) && near >= 0.0, "near", "must be a number >= 0");
  require(std::isfinite(far) && far > near, "far", "must be a number above near");
  tan_half_x_ = std::tan(fovx / 2.0);
  tan_half_y_ = std::tan(fovy / 2.0);
}

Frustum Frustum::defaults() {
  return Frustum(30.0 * M_PI / 180.0, 20.0 * M_PI / 180.0, 0.4, 1.5);
}

Frustum Frustum::fromIntrinsics(int width, int height, double fx, double fy, double near,
                                double far) {
  require(width > 0 && height > 0, "image size", "must be positive");
  require(std::isfinite(fx) && fx > 0.0, "fx", "must be positive");
  require(std::isfinite(fy) && fy > 0.0, "fy", "must be positive");
  return Frustum(2.0 * std::atan(width / (2.0 * fx)), 2.0 * std::atan(height / (2.0 * fy)), near,
                 far);
}

bool Frustum::contains(const Eigen::Vector3d& p) const {
  return p.z() >= near_ && p.z() <= far_ && std::abs(p.x()) <= p.z() * tan_half_x_ &&
         std::abs(p.y()) <= p.z() * tan_half_y_;
}

}  // namespace asr_robot_model
