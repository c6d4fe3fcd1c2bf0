#include "asr_pose_prediction/confidence_split.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "asr_common/input_error.hpp"

namespace asr_pose_prediction {

std::vector<std::size_t> splitByConfidence(std::size_t total,
                                           const std::vector<double>& confidences) {
  std::vector<std::size_t> counts(confidences.size(), 0);
  if (confidences.empty())
    return counts;
  double sum = 0.0;
  for (double confidence : confidences) {
    if (!std::isfinite(confidence) || confidence < 0.0) {
      throw asr_common::InputError("instance confidence " + std::to_string(confidence) +
                                   " cannot weight predicted poses (must be finite and >= 0)");
    }
    sum += confidence;
  }
  // Fractions on a grid of 1e-9, so that rounding noise cannot reorder equal fractions.
  std::vector<long long> fractions(confidences.size());
  std::size_t assigned = 0;
  for (std::size_t i = 0; i < confidences.size(); ++i) {
    const double share = sum > 0.0 ? confidences[i] / sum : 1.0 / confidences.size();
    const double quota = static_cast<double>(total) * share;
    counts[i] = std::min(total - assigned, static_cast<std::size_t>(std::floor(quota)));
    assigned += counts[i];
    fractions[i] = std::llround((quota - std::floor(quota)) * 1e9);
  }
  std::vector<std::size_t> order(confidences.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return fractions[a] > fractions[b]; });
  for (std::size_t k = 0; assigned < total; k = (k + 1) % order.size()) {
    ++counts[order[k]];
    ++assigned;
  }
  return counts;
}

}  // namespace asr_pose_prediction
