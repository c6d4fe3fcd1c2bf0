#include "asr_ism_tree/incremental_recognition.hpp"

#include <algorithm>

#include "asr_ism_tree/estimate_matching.hpp"

namespace asr_ism_tree {

namespace {

// Indices (in configuration order) of the estimates the scene of `tree` can match.
std::vector<int> matchableEstimates(const IsmTree& tree,
                                    const asr_common::Configuration& configuration) {
  const EstimateMatching matching = matchEstimates(tree.objects(), configuration);
  std::vector<int> matchable;
  for (std::size_t i = 0; i < configuration.size(); ++i) {
    if (!matching.candidates[i].empty())
      matchable.push_back(static_cast<int>(i));
  }
  return matchable;
}

// Bit for bit: an estimate that moved by rounding only may change the answer as well.
bool sameEstimates(const asr_common::Configuration& a, const asr_common::Configuration& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const auto& x, const auto& y) {
    return x.key == y.key && x.pose.position == y.pose.position &&
           x.pose.orientation.coeffs() == y.pose.orientation.coeffs();
  });
}

// Replaces each object's `estimate` by to[estimate]: between the configuration and the
// estimates a scene can match (both directions).
void renumberEstimates(std::vector<SceneInstance>& instances, const std::vector<int>& to) {
  for (SceneInstance& instance : instances) {
    for (InstanceObject& object : instance.objects) {
      if (object.estimate >= 0)
        object.estimate = to[object.estimate];
    }
  }
}

}  // namespace

std::vector<SceneInstance> IncrementalRecognition::recognize(
    const std::shared_ptr<const SceneModels>& models,
    const asr_common::Configuration& configuration) {
  if (models != models_) {
    results_.assign(models->scenes().size(), {});
    models_ = models;
  }
  try {
    return recognizeChangedScenes(configuration);
  } catch (...) {
    models_.reset();  // nothing half-updated is kept
    results_.clear();
    throw;
  }
}

std::vector<SceneInstance> IncrementalRecognition::recognizeChangedScenes(
    const asr_common::Configuration& configuration) {
  const std::size_t scenes = results_.size();
  // Too many estimates is refused whatever a scene can match: every scene then runs into it.
  const bool refused = configuration.size() > models_->parameters().max_estimates;
  if (!refused)
    asr_common::validatedPoses(configuration);  // throws as each scene's recognition would
  std::vector<std::vector<int>> matchable(scenes);
  std::vector<std::size_t> changed;
  for (std::size_t scene = 0; scene < scenes; ++scene) {
    matchable[scene] = matchableEstimates(models_->tree(scene), configuration);
    asr_common::Configuration estimates;
    for (int i : matchable[scene])
      estimates.push_back(configuration[i]);
    SceneResult& last = results_[scene];
    if (refused || !last.recognized || !sameEstimates(estimates, last.matchable)) {
      changed.push_back(scene);
      last.matchable = std::move(estimates);
      last.recognized = true;
    }
  }
  recognized_anew_ = changed.size();
  std::vector<std::vector<SceneInstance>> found = models_->recognizeEach(changed, configuration);
  for (std::size_t i = 0; i < changed.size(); ++i) {
    std::vector<int> position_of(configuration.size(), -1);
    for (std::size_t k = 0; k < matchable[changed[i]].size(); ++k)
      position_of[matchable[changed[i]][k]] = static_cast<int>(k);
    renumberEstimates(found[i], position_of);
    results_[changed[i]].instances = std::move(found[i]);
  }
  std::vector<SceneInstance> instances;
  for (std::size_t scene = 0; scene < scenes; ++scene) {
    std::vector<SceneInstance> kept = results_[scene].instances;
    renumberEstimates(kept, matchable[scene]);
    instances.insert(instances.end(), kept.begin(), kept.end());
  }
  sortByConfidence(instances);
  return instances;
}

}  // namespace asr_ism_tree
