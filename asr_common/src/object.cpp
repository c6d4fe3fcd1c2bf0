#include "asr_common/object.hpp"

namespace asr_common {

std::string ObjectKey::toString() const {
  return id.empty() ? type : type + ":" + id;
}

std::vector<Pose> validatedPoses(const Configuration& configuration) {
  std::vector<Pose> poses;
  poses.reserve(configuration.size());
  for (std::size_t i = 0; i < configuration.size(); ++i) {
    const ObjectEstimate& estimate = configuration[i];
    poses.push_back(validatedPose(
        estimate.pose.position, estimate.pose.orientation,
        "object estimate " + std::to_string(i) + " (" + estimate.key.toString() + ")"));
  }
  return poses;
}

}  // namespace asr_common
