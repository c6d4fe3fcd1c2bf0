#pragma once

#include <Eigen/Core>
#include <array>
#include <memory>
#include <vector>

#include "asr_common/object.hpp"
#include "asr_common/pose.hpp"
#include "asr_robot_model/camera_intrinsics.hpp"
#include "asr_robot_model/grey_image.hpp"
#include "asr_robot_model/tag_map.hpp"

namespace asr_robot_model {

struct TagDetectorSettings {
  double decimate = 2.0;             // libapriltag's quad_decimate (corners refined at full size)
  int threads = 1;                   // libapriltag's worker threads
  int max_hamming = 1;               // bit errors a decoded tag may have had corrected
  double min_decision_margin = 20;   // libapriltag's decoding confidence; lower: refused
  double max_reprojection_px = 1.5;  // RMS corner error of a tag's pose; higher: refused

  /// Throws asr_common::InputError naming the setting if one is out of range.
  void check() const;
};

/// A decoded tag of the map, its pose in the camera optical frame.
struct TagEstimate {
  int id = 0;
  asr_common::Pose pose;
  double reprojection_px = 0.0;            // RMS over its 4 corners
  std::array<Eigen::Vector2d, 4> corners;  // pixels as detected: top-left, top-right,
                                           // bottom-right, bottom-left of the printed tag
};

/// An object seen through its tags: its pose in the camera optical frame and a covariance over
/// (x, y, z, rotation about x, y, z) from the corners' reprojection error.
struct ObjectDetection {
  asr_common::ObjectKey key;
  asr_common::Pose pose;
  Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Zero();
  std::vector<int> tags;
  double reprojection_px = 0.0;
};

struct TagDetections {
  std::vector<TagEstimate> tags;
  std::vector<ObjectDetection> objects;
  std::vector<int> unknown_ids;  // decoded, but not in the tag map: ignored
  int refused = 0;               // decoded tags refused for a poor decode or pose fit
};

/// AprilTag object localisation: libapriltag finds and decodes the tags; each known tag's pose
/// comes from OpenCV's solvePnP (SOLVEPNP_IPPE_SQUARE, the better of its two solutions) on the
/// undistorted corners; the tags of one object are combined by refining one object pose on all
/// their corners (Levenberg-Marquardt from the best tag's pose). docs/robot.md says why.
class TagDetector {
 public:
  /// Throws asr_common::InputError for bad settings or an unknown family.
  TagDetector(TagMap map, TagDetectorSettings settings = {});
  ~TagDetector();
  TagDetector(const TagDetector&) = delete;
  TagDetector& operator=(const TagDetector&) = delete;

  /// Throws asr_common::InputError if the image is empty or the intrinsics are unusable.
  TagDetections detect(const GreyImage& image, const CameraIntrinsics& camera) const;

  const TagMap& tagMap() const { return map_; }

 private:
  struct Library;
  /// One object's pose from its tags `indices` (of `tags`, with undistorted corners `pixels`).
  ObjectDetection combineTags(const asr_common::ObjectKey& key,
                              const std::vector<std::size_t>& indices,
                              const std::vector<TagEstimate>& tags,
                              const std::vector<std::vector<Eigen::Vector2d>>& pixels,
                              const CameraIntrinsics& camera) const;

  TagMap map_;
  TagDetectorSettings settings_;
  std::unique_ptr<Library> library_;
};

}  // namespace asr_robot_model
