#include "asr_ism_tree/estimate_matching.hpp"

#include <limits>

namespace asr_ism_tree {

EstimateMatching matchEstimates(const std::vector<ObjectKey>& scene_objects,
                                const asr_common::Configuration& configuration) {
  EstimateMatching matching;
  matching.candidates.resize(configuration.size());
  for (std::size_t e = 0; e < configuration.size(); ++e) {
    const ObjectKey& key = configuration[e].key;
    std::vector<int>& candidates = matching.candidates[e];
    for (std::size_t o = 0; o < scene_objects.size(); ++o) {
      if (scene_objects[o] == key) {
        candidates = {static_cast<int>(o)};
        break;
      }
      if (scene_objects[o].type == key.type)
        candidates.push_back(static_cast<int>(o));
    }
    const bool exact = candidates.size() == 1 && scene_objects[candidates[0]] == key;
    if (!candidates.empty() && !exact)
      matching.ids_ignored = true;
  }
  return matching;
}

std::size_t EstimateMatching::labellingCount() const {
  std::size_t count = 1;
  for (const auto& objects : candidates) {
    if (objects.size() < 2)
      continue;
    if (count > std::numeric_limits<std::size_t>::max() / objects.size())
      return std::numeric_limits<std::size_t>::max();
    count *= objects.size();
  }
  return count;
}

std::vector<std::vector<int>> EstimateMatching::estimatesOfObjects(
    std::size_t index, std::size_t object_count, const std::vector<int>& estimate_order) const {
  // Labelling `index` read as a mixed-radix number, one digit per estimate with several
  // candidates, in `estimate_order` (so that neither the input order nor where the world frame
  // lies decides which labelling comes first).
  std::vector<int> chosen(candidates.size(), -1);
  for (int e : estimate_order) {
    const auto& objects = candidates[e];
    if (objects.empty())
      continue;
    chosen[e] = objects[index % objects.size()];
    index /= objects.size();
  }
  std::vector<std::vector<int>> estimates(object_count);
  for (int e : estimate_order) {
    if (chosen[e] >= 0)
      estimates[chosen[e]].push_back(e);
  }
  return estimates;
}

}  // namespace asr_ism_tree
