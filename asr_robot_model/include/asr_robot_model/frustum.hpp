#pragma once

#include <Eigen/Core>

namespace asr_robot_model {

/// The camera's view volume in camera_optical_frame (z forward, x right, y down): a point p is
/// inside iff near <= z <= far, |x| <= z tan(fovx / 2) and |y| <= z tan(fovy / 2).
class Frustum {
 public:
  /// Full opening angles in radians (0 < fov < pi) and clipping distances in metres
  /// (0 <= near < far). Throws asr_common::InputError naming the field otherwise.
  Frustum(double fovx, double fovy, double near, double far);

  /// The original robot's camera: 30 x 20 deg, 0.4 to 1.5 m.
  static Frustum defaults();

  /// From pinhole intrinsics (the image size in pixels and the focal lengths fx = K[0],
  /// fy = K[4] of a sensor_msgs/CameraInfo): fov = 2 atan(size / (2 f)).
  static Frustum fromIntrinsics(int width, int height, double fx, double fy, double near,
                                double far);

  bool contains(const Eigen::Vector3d& point_in_camera) const;

  double fovx() const { return fovx_; }
  double fovy() const { return fovy_; }
  double near() const { return near_; }
  double far() const { return far_; }

 private:
  double fovx_, fovy_, near_, far_;
  double tan_half_x_, tan_half_y_;
};

}  // namespace asr_robot_model
