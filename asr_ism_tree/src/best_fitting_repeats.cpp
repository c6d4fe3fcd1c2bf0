#include "best_fitting_repeats.hpp"

#include <algorithm>
#include <utility>

namespace asr_ism_tree {
namespace {

// How far `pose` lies from the expected poses `where`: the sum of the squared distance and angle,
// each in units of `tolerance`.
double deviationFrom(const asr_common::Pose& pose, const std::vector<const ExpectedPose*>& where,
                     const RepeatedDetectionTolerance& tolerance) {
  double deviation = 0.0;
  for (const ExpectedPose* there : where) {
    const double distance = (pose.position - there->pose.position).norm() / tolerance.distance;
    const double angle =
        asr_common::angleBetween(pose.orientation, there->pose.orientation) / tolerance.angle;
    deviation += distance * distance + angle * angle;
  }
  return deviation;
}

// Marks in `chosen` the `count` of `estimates` (indices into `poses`) nearest to `where`; the
// first of equals wins.
void markNearest(const std::vector<int>& estimates, const std::vector<asr_common::Pose>& poses,
                 const std::vector<const ExpectedPose*>& where,
                 const RepeatedDetectionTolerance& tolerance, std::size_t count,
                 std::vector<bool>& chosen) {
  std::vector<std::pair<double, std::size_t>> ranked;
  ranked.reserve(estimates.size());
  for (std::size_t i = 0; i < estimates.size(); ++i)
    ranked.emplace_back(deviationFrom(poses[estimates[i]], where, tolerance), i);
  count = std::min(count, ranked.size());
  std::partial_sort(ranked.begin(), ranked.begin() + count, ranked.end());
  for (std::size_t k = 0; k < count; ++k)
    chosen[ranked[k].second] = true;
}

}  // namespace

std::vector<std::vector<int>> bestFittingRepeats(
    const std::vector<ExpectedPose>& expected, const std::vector<std::vector<int>>& representatives,
    const std::vector<std::vector<int>>& every_estimate, const std::vector<asr_common::Pose>& poses,
    const RepeatedDetectionTolerance& tolerance, std::size_t per_object, bool nearest_to_each) {
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
    // Nearest to all its expected poses at once, and nearest to each: where several ISMs hold
    // the object, the best instance may match a different repeat in each.
    std::vector<bool> taken(every_estimate[object].size(), false);
    markNearest(every_estimate[object], poses, where, tolerance, per_object, taken);
    if (nearest_to_each && where.size() > 1) {
      for (const ExpectedPose* there : where)
        markNearest(every_estimate[object], poses, {there}, tolerance, per_object, taken);
    }
    for (std::size_t i = 0; i < taken.size(); ++i) {
      if (taken[i])
        chosen[object].push_back(every_estimate[object][i]);
    }
  }
  return chosen;
}

}  // namespace asr_ism_tree
