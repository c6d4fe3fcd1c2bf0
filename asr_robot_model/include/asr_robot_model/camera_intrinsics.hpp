#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace asr_robot_model {

/// A pinhole camera with plumb-bob distortion (k1, k2, p1, p2, k3), as ROS's CameraInfo and
/// OpenCV's calibration describe it. Pixel (0, 0)'s centre is at coordinates (0, 0).
struct CameraIntrinsics {
  int width = 640;
  int height = 480;
  double fx = 0.0, fy = 0.0, cx = 0.0, cy = 0.0;
  std::vector<double> distortion;  // empty or all zero: none

  /// Square pixels, principal point in the middle, no distortion. Throws
  /// asr_common::InputError for a non-positive size or a field of view outside (0, 180) deg.
  static CameraIntrinsics fromHorizontalFov(int width, int height, double horizontal_fov);
  /// 640 x 480, 60 degrees horizontal field of view (the suite's simulated camera).
  static CameraIntrinsics defaults();

  Eigen::Matrix3d matrix() const;
  /// Throws asr_common::InputError naming `what` and the field if a value is unusable.
  void check(const std::string& what) const;
};

/// Reads a camera calibration in ROS's camera_calibration YAML format (image_width,
/// image_height, camera_matrix.data, distortion_model, distortion_coefficients.data). Throws
/// asr_common::InputError naming the file and the field if it is missing or malformed.
CameraIntrinsics loadCameraInfo(const std::string& path);

/// Writes `camera` in the format loadCameraInfo reads.
void saveCameraInfo(const std::string& path, const CameraIntrinsics& camera,
                    const std::string& camera_name = "asr_camera");

}  // namespace asr_robot_model
