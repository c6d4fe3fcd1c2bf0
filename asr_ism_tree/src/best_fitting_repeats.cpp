#include "best_fitting_repeats.hpp"

#include <algorithm>
#include <limits>

namespace asr_ism_tree {

std::vector<std::vector<int>> bestFittingRepeats(
    const std::vector<ExpectedPose>& expected, const std::vector<std::vector<int>>& representatives,
    const std::vector<std::vector<int>>& every_estimate, const std::vector<asr_common::Pose>& poses,
    const RepeatedDetectionTolerance& tolerance) {
  std::vector<std::vector<int>> chosen(every_estimate.size());
  for (std::size_t object = 0; object < every_estimate.size(); ++object) {
    std::vector<const ExpectedPose*> where;
    std::vector<int> keep = representatives[object];
    for (const ExpectedPose& pose : expected) {
      if (pose.object != static_cast<int>(object))
        continue;
      where.push_back(&pose);
      keep.erase(std::remove(keep.begin(), keep.end(), pose.estimate), keep.end());
    }
    if (!where.empty()) {
      int best = -1;
      double best_deviation = std::numeric_limits<double>::infinity();
      for (int estimate : every_estimate[object]) {
        double deviation = 0.0;
        for (const ExpectedPose* pose : where) {
          const double distance =
              (poses[estimate].position - pose->pose.position).norm() / tolerance.distance;
          const double angle =
              asr_common::angleBetween(poses[estimate].orientation, pose->pose.orientation) /
              tolerance.angle;
          deviation += distance * distance + angle * angle;
        }
        if (deviation < best_deviation) {
          best_deviation = deviation;
          best = estimate;
        }
      }
      keep.push_back(best);
    }
    for (int estimate : every_estimate[object]) {
      if (std::find(keep.begin(), keep.end(), estimate) != keep.end())
        chosen[object].push_back(estimate);
    }
  }
  return chosen;
}

}  // namespace asr_ism_tree
