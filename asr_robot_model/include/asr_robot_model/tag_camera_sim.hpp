#pragma once

#include <vector>

#include "asr_common/pose.hpp"
#include "asr_robot_model/camera_intrinsics.hpp"
#include "asr_robot_model/grey_image.hpp"
#include "asr_robot_model/tag_family.hpp"
#include "asr_robot_model/tag_map.hpp"
#include "asr_robot_model/world.hpp"

namespace asr_robot_model {

struct CameraSimSettings {
  CameraIntrinsics camera = CameraIntrinsics::defaults();
  bool occlusion = true;     // furniture and other objects hide the tags behind them
  double noise_sigma = 2.0;  // grey levels, Gaussian, per pixel
  double blur_sigma = 0.5;   // pixels, Gaussian (the lens' softness); 0: none
  int supersampling = 4;     // samples per pixel and axis where a tag is drawn

  /// Throws asr_common::InputError naming the setting if one is out of range.
  void check() const;
};

/// The simulated camera: what a greyscale camera at a pose in a world sees. Furniture and object
/// boxes are ray-cast and shaded by the angle they are seen at; each tag of the tag map whose
/// object is in the world and whose printed face turns towards the camera is drawn on its
/// object by sampling the family's bitmap along each pixel's ray (a perspective warp,
/// antialiased by supersampling), hidden where another box is nearer. Blur and noise follow;
/// the same seed gives the same image.
class TagCameraSim {
 public:
  /// Throws asr_common::InputError for bad settings or a tag id outside the map's family.
  TagCameraSim(const World& world, const TagMap& tags, CameraSimSettings settings);

  /// The image from camera_optical_frame at `camera` (in the world's frame).
  GreyImage render(const asr_common::Pose& camera, unsigned seed) const;

  /// The ids of the drawn tags whose printed face turns towards `camera` and whose corners all
  /// lie in front of it and inside the image (occlusion not considered).
  std::vector<int> tagsInView(const asr_common::Pose& camera) const;

  /// Each drawn tag's pose in the world (for tests: the truth the detector is measured against).
  const std::vector<std::pair<int, asr_common::Pose>>& tagPoses() const { return tag_poses_; }
  const CameraSimSettings& settings() const { return settings_; }

 private:
  struct DrawnTag {
    int id;
    Eigen::Vector3d centre, x_axis, y_axis, normal;  // world frame
    double half_width;                               // of the printed tag, with its margin
    double cell;                                     // metres per bitmap cell
    GreyImage bitmap;
    int own_box;  // the box of its object, which must not hide it
  };
  struct RayBox {
    Eigen::Matrix3d to_box;  // world to box rotation
    Eigen::Vector3d centre, half_size;
  };

  /// Distance factor t (point = eye + t * direction) of the nearest box hit beyond `near`, the
  /// hit box's index (-1: none) and the shade of the face hit.
  double nearestBox(const Eigen::Vector3d& eye, const Eigen::Vector3d& direction, int skip,
                    int& hit, double& shade) const;
  void drawTag(const DrawnTag& tag, const asr_common::Pose& camera,
               std::vector<double>& image) const;
  bool facesCamera(const DrawnTag& tag, const Eigen::Vector3d& eye) const;
  Eigen::Vector3d rayDirection(const asr_common::Pose& camera, double x, double y) const;

  CameraSimSettings settings_;
  TagFamily family_;
  std::vector<RayBox> boxes_;
  std::vector<DrawnTag> tags_;
  std::vector<std::pair<int, asr_common::Pose>> tag_poses_;
};

}  // namespace asr_robot_model
