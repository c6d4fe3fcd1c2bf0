#include "asr_pose_prediction/relation_sampler.hpp"

#include <algorithm>
#include <limits>

#include "asr_common/input_error.hpp"
#include "asr_ism/portable_random.hpp"

namespace asr_pose_prediction {

RelationSampler::RelationSampler(const asr_ism::IsmMember& member, const std::string& what) {
  if (member.relative_poses.empty())
    throw asr_common::InputError(what + ": no relative pose to predict from");
  std::uint64_t total = 0;
  for (const asr_ism::RelativePose& relative : member.relative_poses) {
    if (relative.step_count == 0)
      throw asr_common::InputError(what + ": a relative pose with a step count of 0");
    total += relative.step_count;
    if (total > std::numeric_limits<std::uint32_t>::max())
      throw asr_common::InputError(what + ": more than 2^32 demonstrated steps");
    member_in_reference_.push_back(asr_common::inverse(relative.reference_in_member));
    cumulative_steps_.push_back(static_cast<std::uint32_t>(total));
  }
}

const asr_common::Pose& RelationSampler::sample(std::mt19937& engine) const {
  if (member_in_reference_.size() == 1)
    return member_in_reference_.front();
  const std::uint32_t step = asr_ism::uniformBelow(engine, cumulative_steps_.back());
  const auto chosen = std::upper_bound(cumulative_steps_.begin(), cumulative_steps_.end(), step);
  return member_in_reference_[static_cast<std::size_t>(chosen - cumulative_steps_.begin())];
}

}  // namespace asr_pose_prediction
