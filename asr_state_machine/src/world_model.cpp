#include "asr_state_machine/world_model.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "asr_common/input_error.hpp"

namespace asr_state_machine {

namespace {

bool finitePose(const Pose& pose) {
  return pose.position.allFinite() && pose.orientation.coeffs().allFinite();
}

// The mean of `count` poses in `mean` and one more: positions averaged, quaternions summed on
// the same hemisphere and normalised (exact enough for the small spread of repeated estimates).
Pose runningMean(const Pose& mean, int count, const Pose& next) {
  const double weight = 1.0 / (count + 1);
  Eigen::Vector3d position = mean.position + weight * (next.position - mean.position);
  Eigen::Vector4d sum = mean.orientation.coeffs() * count;
  Eigen::Vector4d added = next.orientation.coeffs();
  if (sum.dot(added) < 0.0)
    added = -added;
  sum += added;
  Eigen::Quaterniond orientation(sum(3), sum(0), sum(1), sum(2));
  return Pose(position, asr_common::canonicalQuaternion(orientation));
}

}  // namespace

WorldModel::WorldModel(MergeTolerance tolerance) : tolerance_(tolerance) {}

void WorldModel::setSceneObjects(
    const std::map<std::string, std::vector<ObjectKey>>& scene_objects) {
  scene_objects_ = scene_objects;
}

std::optional<std::size_t> WorldModel::matchingObject(const ObjectEstimate& estimate) const {
  std::optional<std::size_t> nearest;
  double nearest_distance = tolerance_.distance;
  for (std::size_t i = 0; i < found_.size(); ++i) {
    const FoundObject& found = found_[i];
    if (found.key.type != estimate.key.type)
      continue;
    const bool ids_differ =
        !estimate.key.id.empty() && !found.key.id.empty() && estimate.key.id != found.key.id;
    if (ids_differ)
      continue;
    const double distance = (found.pose.position - estimate.pose.position).norm();
    // Equal ids are one object wherever it was seen; otherwise only nearby estimates merge.
    if (!estimate.key.id.empty() && found.key.id == estimate.key.id)
      return i;
    if (distance < nearest_distance) {
      nearest = i;
      nearest_distance = distance;
    }
  }
  return nearest;
}

WorldModel::Added WorldModel::addEstimate(const ObjectEstimate& estimate, double at_s, int view) {
  if (!finitePose(estimate.pose)) {
    throw asr_common::InputError("world model: estimate of " + estimate.key.toString() +
                                 " has a non-finite pose");
  }
  if (const auto match = matchingObject(estimate)) {
    FoundObject& found = found_[*match];
    found.pose = runningMean(found.pose, found.estimates, estimate.pose);
    ++found.estimates;
    if (found.key.id.empty())
      found.key.id = estimate.key.id;
    return {*match, false};
  }
  FoundObject found;
  found.key = estimate.key;
  found.pose =
      Pose(estimate.pose.position, asr_common::canonicalQuaternion(estimate.pose.orientation));
  found.estimates = 1;
  found.found_at_s = at_s;
  found.view = view;
  found_.push_back(found);
  return {found_.size() - 1, true};
}

int WorldModel::addView(const VisitedView& view) {
  views_.push_back(view);
  return static_cast<int>(views_.size()) - 1;
}

asr_common::Configuration WorldModel::configuration() const {
  asr_common::Configuration configuration;
  for (const FoundObject& found : found_)
    configuration.push_back({found.key, found.pose});
  return configuration;
}

std::vector<ObjectKey> WorldModel::missingObjects(const std::string& scene) const {
  const auto entry = scene_objects_.find(scene);
  if (entry == scene_objects_.end()) {
    throw asr_common::InputError("world model: no scene '" + scene + "'");
  }
  const std::vector<ObjectKey>& objects = entry->second;
  std::vector<char> covered(objects.size(), 0);
  std::vector<char> used(found_.size(), 0);
  // Exact keys first, then found objects the scene cannot tell by id stand in for one
  // uncovered object of their type each.
  for (std::size_t o = 0; o < objects.size(); ++o) {
    for (std::size_t f = 0; f < found_.size(); ++f) {
      if (!used[f] && found_[f].key == objects[o]) {
        covered[o] = used[f] = 1;
        break;
      }
    }
  }
  for (std::size_t o = 0; o < objects.size(); ++o) {
    if (covered[o])
      continue;
    for (std::size_t f = 0; f < found_.size(); ++f) {
      if (used[f] || found_[f].key.type != objects[o].type)
        continue;
      const bool id_known = std::any_of(objects.begin(), objects.end(),
                                        [&](const ObjectKey& k) { return k == found_[f].key; });
      if (id_known)
        continue;
      covered[o] = used[f] = 1;
      break;
    }
  }
  std::vector<ObjectKey> missing;
  for (std::size_t o = 0; o < objects.size(); ++o) {
    if (!covered[o])
      missing.push_back(objects[o]);
  }
  return missing;
}

std::vector<ObjectKey> WorldModel::missingObjects() const {
  std::set<ObjectKey> missing;
  for (const auto& [scene, objects] : scene_objects_) {
    for (const ObjectKey& key : missingObjects(scene))
      missing.insert(key);
  }
  return {missing.begin(), missing.end()};
}

std::vector<std::string> WorldModel::missingTypes() const {
  std::set<std::string> types;
  for (const ObjectKey& key : missingObjects())
    types.insert(key.type);
  return {types.begin(), types.end()};
}

bool WorldModel::isMissing(const ObjectKey& key) const {
  const std::vector<ObjectKey> missing = missingObjects();
  return std::find(missing.begin(), missing.end(), key) != missing.end();
}

void WorldModel::setSceneConfidence(const std::string& scene, double confidence) {
  confidences_[scene] = confidence;
}

double WorldModel::sceneConfidence(const std::string& scene) const {
  const auto entry = confidences_.find(scene);
  return entry == confidences_.end() ? 0.0 : entry->second;
}

void WorldModel::clear() {
  found_.clear();
  views_.clear();
  confidences_.clear();
}

}  // namespace asr_state_machine
