#include "best_fitting_repeats.hpp"

#include <algorithm>
#include <utility>

namespace asr_ism_tree {

std::vector<std::vector<int>> bestFittingRepeats(
    const std::vector<ExpectedPose>& expected, const std::vector<std::vector<int>>& representatives,
    const std::vector<std::vector<int>>& every_estimate, const std::vector<asr_common::Pose>& poses,
    const RepeatedDetectionTolerance& tolerance, std::size_t per_object) {
  std::vector<std::vector<int>> chosen(every_estimate.size());
  for (std::size_t object = 0; object < every_estimate.size(); ++object) {
    std::vector<const ExpectedPose*> where;
    for (const ExpectedPose& pose : expected) {
      if (pose.object == static_cast<int>(object))
        where.push_back(&pose);
    }
    if (where.empty()) {
      chosen[object] = representatives[object];
      continue;
    }
    // (deviation, position in every_estimate): the first of equals wins.
    std::vector<std::pair<double, std::size_t>> ranked;
    for (std::size_t i = 0; i < every_estimate[object].size(); ++i) {
      const asr_common::Pose& pose = poses[every_estimate[object][i]];
      double deviation = 0.0;
      for (const ExpectedPose* there : where) {
        const double distance = (pose.position - there->pose.position).norm() / tolerance.distance;
        const double angle =
            asr_common::angleBetween(pose.orientation, there->pose.orientation) / tolerance.angle;
        deviation += distance * distance + angle * angle;
      }
      ranked.emplace_back(deviation, i);
    }
    const std::size_t count = std::min(per_object, ranked.size());
    std::partial_sort(ranked.begin(), ranked.begin() + count, ranked.end());
    ranked.resize(count);
    std::sort(ranked.begin(), ranked.end(),
              [](const auto& a, const auto& b) { return a.second < b.second; });
    for (const auto& [deviation, i] : ranked)
      chosen[object].push_back(every_estimate[object][i]);
  }
  return chosen;
}

}  // namespace asr_ism_tree
