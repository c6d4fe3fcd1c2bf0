#include "matchable_estimates.hpp"

#include <algorithm>

#include "asr_ism_tree/estimate_matching.hpp"

namespace asr_ism_tree {

asr_common::Configuration matchableEstimates(const IsmTree& tree,
                                             const asr_common::Configuration& configuration) {
  const EstimateMatching matching = matchEstimates(tree.objects(), configuration);
  asr_common::Configuration matchable;
  for (std::size_t i = 0; i < configuration.size(); ++i) {
    if (!matching.candidates[i].empty())
      matchable.push_back(configuration[i]);
  }
  return matchable;
}

bool sameEstimates(const asr_common::Configuration& a, const asr_common::Configuration& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const auto& x, const auto& y) {
    return x.key == y.key && x.pose.position == y.pose.position &&
           x.pose.orientation.coeffs() == y.pose.orientation.coeffs();
  });
}

}  // namespace asr_ism_tree
