#include "asr_nbv/hypotheses.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "asr_common/input_error.hpp"

namespace asr_nbv {
namespace {

bool finitePose(const asr_common::Pose& pose) {
  return pose.position.allFinite() && pose.orientation.coeffs().allFinite();
}

Hypothesis makeHypothesis(const asr_common::ObjectKey& key, const asr_common::Pose& pose,
                          const asr_robot_model::ObjectType* type) {
  Hypothesis hypothesis;
  hypothesis.key = key;
  hypothesis.box.pose = pose;
  hypothesis.box.size = type != nullptr ? type->size : Eigen::Vector3d::Constant(kUnknownTypeSize);
  if (type != nullptr) {
    for (const Eigen::Vector3d& normal : type->normals)
      hypothesis.normals.push_back((pose.orientation * normal).normalized());
  }
  hypothesis.active.assign(std::max<std::size_t>(1, hypothesis.normals.size()), 1);
  hypothesis.active_count = static_cast<int>(hypothesis.active.size());
  return hypothesis;
}

}  // namespace

HypothesisSet::HypothesisSet(const std::vector<PredictedCloud>& clouds,
                             const asr_robot_model::ObjectCatalogue& catalogue) {
  std::set<std::string> types, unknown;
  for (const PredictedCloud& cloud : clouds) {
    const auto entry = catalogue.find(cloud.key.type);
    const asr_robot_model::ObjectType* type = entry != catalogue.end() ? &entry->second : nullptr;
    for (const asr_common::Pose& pose : cloud.poses) {
      asr_common::Pose valid;
      try {
        if (!finitePose(pose))
          throw asr_common::InputError("not finite");
        valid = asr_common::validatedPose(pose.position, pose.orientation, cloud.key.toString());
      } catch (const asr_common::InputError&) {
        ++rejected_poses_;
        continue;
      }
      if (type == nullptr)
        unknown.insert(cloud.key.type);
      types.insert(cloud.key.type);
      made_.push_back(makeHypothesis(cloud.key, valid, type));
    }
  }
  types_.assign(types.begin(), types.end());
  for (Hypothesis& hypothesis : made_)
    hypothesis.type = typeIndex(hypothesis.key.type);
  for (const std::string& type : unknown)
    warnings_.push_back("type '" + type +
                        "' is not in the object catalogue: searched as recognisable from every "
                        "side");
  if (rejected_poses_ > 0)
    warnings_.push_back(std::to_string(rejected_poses_) +
                        " predicted poses rejected (not finite or quaternion not unit length)");
  hypotheses_ = made_;
}

int HypothesisSet::typeIndex(const std::string& type) const {
  const auto found = std::lower_bound(types_.begin(), types_.end(), type);
  return found != types_.end() && *found == type ? static_cast<int>(found - types_.begin()) : -1;
}

std::size_t HypothesisSet::countingHypotheses() const {
  return static_cast<std::size_t>(std::count_if(hypotheses_.begin(), hypotheses_.end(),
                                                [](const Hypothesis& h) { return h.counts(); }));
}

std::size_t HypothesisSet::countingTypes() const {
  std::vector<char> counting(types_.size(), 0);
  for (const Hypothesis& hypothesis : hypotheses_)
    counting[hypothesis.type] |= hypothesis.counts() ? 1 : 0;
  return static_cast<std::size_t>(std::count(counting.begin(), counting.end(), 1));
}

std::size_t HypothesisSet::removeObjects(const std::vector<asr_common::ObjectKey>& objects) {
  const std::size_t before = hypotheses_.size();
  hypotheses_.erase(
      std::remove_if(hypotheses_.begin(), hypotheses_.end(),
                     [&](const Hypothesis& h) {
                       for (const asr_common::ObjectKey& key : objects) {
                         if (h.key.type == key.type && (key.id.empty() || h.key.id == key.id))
                           return true;
                       }
                       return false;
                     }),
      hypotheses_.end());
  return before - hypotheses_.size();
}

void HypothesisSet::reset() {
  hypotheses_ = made_;
}

}  // namespace asr_nbv
