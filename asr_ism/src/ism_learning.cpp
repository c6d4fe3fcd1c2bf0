#include "asr_ism/ism_learning.hpp"

#include <algorithm>
#include <sstream>
#include <tuple>

#include "asr_ism/common_types.hpp"
#include "asr_ism/input_limits.hpp"

namespace asr_ism {
namespace {

constexpr double kDuplicateTolerance = 1e-9;

// Sorting by position first brings duplicates next to each other, so merging is linear.
std::vector<RelativePose> mergeDuplicates(std::vector<Pose> poses) {
  std::sort(poses.begin(), poses.end(), [](const Pose& a, const Pose& b) {
    return std::make_tuple(a.position.x(), a.position.y(), a.position.z(), a.orientation.w(),
                           a.orientation.x(), a.orientation.y(), a.orientation.z()) <
           std::make_tuple(b.position.x(), b.position.y(), b.position.z(), b.orientation.w(),
                           b.orientation.x(), b.orientation.y(), b.orientation.z());
  });
  std::vector<RelativePose> merged;
  for (const Pose& pose : poses) {
    bool duplicate = false;
    // Scan back over the poses whose x is within tolerance; they may differ in y or z.
    for (auto it = merged.rbegin(); it != merged.rend(); ++it) {
      if (pose.position.x() - it->reference_in_member.position.x() > kDuplicateTolerance) {
        break;
      }
      if (approximatelyEqual(pose, it->reference_in_member, kDuplicateTolerance,
                             kDuplicateTolerance)) {
        ++it->step_count;
        duplicate = true;
        break;
      }
    }
    if (!duplicate) {
      merged.push_back({pose, 1});
    }
  }
  return merged;
}

// A relation longer than any scene spans comes from an outlier pose (a glitch of a detector or a
// recording); learnt, it would make every later recognition vote far out of the scene.
void checkRelationLength(const std::string& ism, const ObjectKey& member,
                         const ObjectKey& reference, std::size_t step, const Pose& relative) {
  const double length = relative.position.norm();
  if (length <= kMaxRelationLength)
    return;
  std::ostringstream message;
  message << "ISM '" << ism << "': in time step " << step << ", " << member.toString() << " is "
          << length << " m from the reference " << reference.toString() << ", more than the "
          << kMaxRelationLength << " m a scene may span; is one of these poses an outlier?";
  throw InputError(message.str());
}

}  // namespace

Ism learnIsm(const std::string& name, const ObjectKey& reference,
             const Trajectory& reference_trajectory, const std::vector<MemberTrajectory>& members) {
  Ism ism;
  ism.name = name;
  ism.reference = reference;
  for (const MemberTrajectory& member : members) {
    if (member.trajectory.size() != reference_trajectory.size()) {
      throw InputError("ISM '" + name + "': trajectory of " + member.object.toString() + " has " +
                       std::to_string(member.trajectory.size()) + " steps, the reference " +
                       std::to_string(reference_trajectory.size()));
    }
    std::vector<Pose> relative;
    for (std::size_t step = 0; step < reference_trajectory.size(); ++step) {
      if (member.trajectory[step] && reference_trajectory[step]) {
        relative.push_back(relativePose(*member.trajectory[step], *reference_trajectory[step]));
        checkRelationLength(name, member.object, reference, step, relative.back());
      }
    }
    if (relative.empty()) {
      throw InputError("ISM '" + name + "': " + member.object.toString() +
                       " is never observed together with the reference " + reference.toString());
    }
    ism.members.push_back({member.object, member.child_ism, mergeDuplicates(std::move(relative))});
  }
  return ism;
}

}  // namespace asr_ism
