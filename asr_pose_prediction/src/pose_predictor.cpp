#include "asr_pose_prediction/pose_predictor.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "asr_common/input_error.hpp"
#include "asr_pose_prediction/confidence_split.hpp"

namespace asr_pose_prediction {

using asr_common::InputError;

std::mt19937 predictionEngine(std::uint32_t seed, std::size_t object, std::size_t stream) {
  // seed_seq's mixing and mt19937's seeding from it are fixed by the standard.
  std::seed_seq sequence{seed, static_cast<std::uint32_t>(object),
                         static_cast<std::uint32_t>(stream)};
  return std::mt19937(sequence);
}

PosePredictor::PosePredictor(const IsmTree& tree)
    : scene_(tree.scene), objects_(tree.objects()), paths_(shortestPredictionPaths(tree)) {
  std::map<std::pair<int, int>, std::size_t> sampler_of_member;
  for (const PredictionPath& path : paths_) {
    path_names_.push_back(ismNames(tree, path));
    std::vector<std::size_t>& samplers = path_samplers_.emplace_back();
    for (const PredictionStep& step : path.steps) {
      const auto [entry, added] =
          sampler_of_member.emplace(std::make_pair(step.ism, step.member), samplers_.size());
      if (added) {
        const asr_ism::Ism& ism = tree.isms[step.ism];
        samplers_.emplace_back(ism.members[step.member],
                               "scene '" + scene_ + "', ISM '" + ism.name + "', member " +
                                   ism.members[step.member].object.toString());
      }
      samplers.push_back(entry->second);
    }
  }
}

std::size_t PosePredictor::objectIndex(const ObjectKey& key) const {
  const auto found = std::find(objects_.begin(), objects_.end(), key);
  if (found == objects_.end())
    throw InputError("scene '" + scene_ + "' has no object " + key.toString());
  return static_cast<std::size_t>(found - objects_.begin());
}

std::vector<std::size_t> PosePredictor::objectsToPredict(const SceneInstance& instance) const {
  if (instance.scene != scene_) {
    throw InputError("an instance of scene '" + instance.scene +
                     "' cannot be predicted with the tree of scene '" + scene_ + "'");
  }
  std::vector<char> contained(objects_.size(), 0);
  for (const asr_ism_tree::InstanceObject& object : instance.objects) {
    if (object.similarity > 0.0)
      contained[objectIndex(object.key)] = 1;
  }
  std::vector<std::size_t> lacking;
  for (std::size_t object = 0; object < objects_.size(); ++object) {
    if (!contained[object])
      lacking.push_back(object);
  }
  return lacking;
}

std::vector<Pose> PosePredictor::predictObject(const Pose& scene_pose, std::size_t object,
                                               std::size_t samples, std::uint32_t seed,
                                               std::size_t stream) const {
  const std::vector<std::size_t>& steps = path_samplers_.at(object);
  std::mt19937 engine = predictionEngine(seed, object, stream);
  std::vector<Pose> poses;
  poses.reserve(samples);
  for (std::size_t i = 0; i < samples; ++i) {
    Pose pose = scene_pose;
    for (std::size_t sampler : steps)
      pose = asr_common::compose(pose, samplers_[sampler].sample(engine));
    poses.push_back(pose);
  }
  return poses;
}

std::vector<ObjectPrediction> PosePredictor::predict(const std::vector<SceneInstance>& instances,
                                                     const PredictionOptions& options) const {
  if (instances.empty())
    throw InputError("scene '" + scene_ + "': no instance to predict from");
  if (options.samples == 0)
    throw InputError("the number of poses to predict per object must be at least 1");
  if (options.instances == 0)
    throw InputError("the number of instances to predict from must be at least 1");
  const std::size_t used = std::min(options.instances, instances.size());

  // lacking[object][rank]: instance `rank` does not contain the object.
  std::vector<std::vector<char>> lacking(objects_.size(), std::vector<char>(used, 0));
  for (std::size_t rank = 0; rank < used; ++rank) {
    for (std::size_t object : objectsToPredict(instances[rank]))
      lacking[object][rank] = 1;
  }
  std::vector<std::size_t> wanted;
  if (options.object) {
    const std::size_t object = objectIndex(*options.object);
    if (std::find(lacking[object].begin(), lacking[object].end(), 1) == lacking[object].end()) {
      throw InputError("scene '" + scene_ + "': " + options.object->toString() +
                       " is in the instance, so there is nothing to predict for it");
    }
    wanted.push_back(object);
  } else {
    for (std::size_t object = 0; object < objects_.size(); ++object)
      wanted.push_back(object);
  }

  std::vector<ObjectPrediction> predictions;
  for (std::size_t object : wanted) {
    std::vector<std::size_t> ranks;  // the instances that lack the object
    std::vector<double> confidences;
    for (std::size_t rank = 0; rank < used; ++rank) {
      if (lacking[object][rank]) {
        ranks.push_back(rank);
        confidences.push_back(instances[rank].confidence);
      }
    }
    if (ranks.empty())
      continue;
    const std::vector<std::size_t> counts = splitByConfidence(options.samples, confidences);

    ObjectPrediction& prediction = predictions.emplace_back();
    prediction.object = objects_[object];
    prediction.object_index = object;
    prediction.path = path_names_[object];
    prediction.poses_per_instance.assign(used, 0);
    prediction.poses.reserve(options.samples);
    for (std::size_t k = 0; k < ranks.size(); ++k) {
      const std::size_t rank = ranks[k];
      prediction.poses_per_instance[rank] = counts[k];
      const std::vector<Pose> poses =
          predictObject(instances[rank].pose, object, counts[k], options.seed, rank);
      prediction.poses.insert(prediction.poses.end(), poses.begin(), poses.end());
    }
  }
  return predictions;
}

}  // namespace asr_pose_prediction
