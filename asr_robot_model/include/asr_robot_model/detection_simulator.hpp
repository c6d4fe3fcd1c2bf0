#pragma once

#include <optional>
#include <random>
#include <string>
#include <vector>

#include "asr_common/object.hpp"
#include "asr_common/pose.hpp"
#include "asr_robot_model/frustum.hpp"
#include "asr_robot_model/world.hpp"
#include "asr_robot_model/world_map.hpp"

namespace asr_robot_model {

struct DetectionSettings {
  Frustum frustum = Frustum::defaults();
  double max_normal_angle = 63.0 * M_PI / 180.0;  // radians
  double position_sigma = 0.0;                    // metres, per axis
  double angle_sigma = 0.0;                       // radians, of a random-axis rotation
  double miss_probability = 0.0;                  // of a detection that would succeed
  double seconds_per_type = 3.0;                  // simulated time per requested type
};

/// Why an object of a requested type was not detected.
enum class Rejection { kFrustum, kNormals, kOccluded, kMissed };
/// "frustum", "normals", "occluded", "missed".
const char* rejectionName(Rejection rejection);

struct RejectedObject {
  asr_common::ObjectKey key;
  Rejection why;
};

struct Detections {
  std::vector<asr_common::ObjectEstimate> detected;  // estimates: true pose plus noise
  std::vector<RejectedObject> rejected;
  double seconds = 0.0;  // simulated time the detection took
};

/// The simulated detector. An object is seen iff all 8 corners of its box lie in the frustum,
/// the camera lies within max_normal_angle of one of its normals (seen from the object; an
/// object without normals passes) and the segment from the camera to its centre meets no voxel
/// of anything else; then it is missed with miss_probability, else reported at its true pose
/// plus seeded Gaussian noise.
class DetectionSimulator {
 public:
  /// Throws asr_common::InputError naming the setting if one is out of range.
  DetectionSimulator(const World& world, const WorldMap& map, DetectionSettings settings,
                     unsigned seed);

  /// Detects the objects of `types` (all types when empty) from camera_optical_frame's pose in
  /// map.
  Detections detect(const asr_common::Pose& camera, const std::vector<std::string>& types);

  /// The geometric verdict alone (no miss, no noise): nothing if seen, else why not.
  std::optional<Rejection> visibility(const asr_common::Pose& camera,
                                      const WorldObject& object) const;

 private:
  asr_common::Pose noisy(const asr_common::Pose& truth);

  const World& world_;
  const WorldMap& map_;
  DetectionSettings settings_;
  std::mt19937 random_;
};

}  // namespace asr_robot_model
