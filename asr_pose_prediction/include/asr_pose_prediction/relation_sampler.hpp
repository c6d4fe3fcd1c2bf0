#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "asr_ism/ism.hpp"

namespace asr_pose_prediction {

/// The relation between an ISM's reference and one member, ready for prediction: every relative
/// pose inverted once (the member seen from the reference), drawn with probability proportional
/// to its step_count, so that samples follow the demonstration (identical steps were merged into
/// one relative pose when the ISM was learned). The draws are the same on every platform: an
/// unbiased integer in [0, total step count) from std::mt19937's raw output (whose sequence the
/// standard fixes), by multiply-and-shift with rejection, not a std:: distribution.
class RelationSampler {
 public:
  /// Throws InputError naming `what` if the member has no relative pose or a step_count of 0.
  RelationSampler(const asr_ism::IsmMember& member, const std::string& what);

  /// One relative pose, member in reference frame. Uses no random number if there is only one.
  const asr_common::Pose& sample(std::mt19937& engine) const;

  std::size_t size() const { return member_in_reference_.size(); }
  const asr_common::Pose& pose(std::size_t index) const { return member_in_reference_[index]; }

 private:
  std::vector<asr_common::Pose> member_in_reference_;
  std::vector<std::uint32_t> cumulative_steps_;  // inclusive prefix sums of step_count
};

}  // namespace asr_pose_prediction
