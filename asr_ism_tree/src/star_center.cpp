#include "asr_ism_tree/star_center.hpp"

#include <limits>

namespace asr_ism_tree {

std::size_t chooseStarCenter(const asr_ism::Demonstration& demonstration) {
  std::size_t best = 0;
  std::size_t best_observed = 0;
  double best_mean_distance = std::numeric_limits<double>::infinity();
  for (std::size_t candidate = 0; candidate < demonstration.objectCount(); ++candidate) {
    std::size_t observed = 0;
    double distance_sum = 0.0;
    std::size_t distance_count = 0;
    for (std::size_t step = 0; step < demonstration.stepCount(); ++step) {
      const auto& pose = demonstration.pose(step, candidate);
      if (!pose)
        continue;
      ++observed;
      for (std::size_t other = 0; other < demonstration.objectCount(); ++other) {
        const auto& other_pose = demonstration.pose(step, other);
        if (other == candidate || !other_pose)
          continue;
        distance_sum += (other_pose->position - pose->position).norm();
        ++distance_count;
      }
    }
    const double mean_distance = distance_count == 0 ? 0.0 : distance_sum / distance_count;
    if (observed > best_observed ||
        (observed == best_observed && mean_distance < best_mean_distance)) {
      best = candidate;
      best_observed = observed;
      best_mean_distance = mean_distance;
    }
  }
  return best;
}

}  // namespace asr_ism_tree
