#include "pose_diverse_results.hpp"

#include <algorithm>

namespace asr_ism_tree {

std::vector<asr_ism::IsmResult> poseDiverseResults(std::vector<asr_ism::IsmResult> results,
                                                   std::size_t count, double radius, double angle) {
  std::vector<asr_ism::IsmResult> kept;
  for (asr_ism::IsmResult& result : results) {
    if (kept.size() >= count)
      break;
    const auto near = [&](const asr_ism::IsmResult& better) {
      return (better.reference_pose.position - result.reference_pose.position).norm() <= radius &&
             asr_common::angleBetween(better.reference_pose.orientation,
                                      result.reference_pose.orientation) <= angle;
    };
    if (std::none_of(kept.begin(), kept.end(), near))
      kept.push_back(std::move(result));
  }
  return kept;
}

}  // namespace asr_ism_tree
