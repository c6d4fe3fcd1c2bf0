#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "asr_ism_tree/ism_tree.hpp"
#include "asr_ism_tree/scene_instance.hpp"
#include "asr_pose_prediction/prediction_path.hpp"
#include "asr_pose_prediction/relation_sampler.hpp"

namespace asr_pose_prediction {

using asr_ism_tree::SceneInstance;

/// The ranges tools and the node accept for the options below.
constexpr long long kMaxSamples = 100000;
constexpr long long kMaxInstances = 1000;

struct PredictionOptions {
  /// Poses predicted per object, over all instances used.
  std::size_t samples = 100;
  std::uint32_t seed = 0;
  /// Predict from the best `instances` instances (those recognised, if fewer), each object's
  /// poses split among the instances that lack it in proportion to their confidences.
  std::size_t instances = 1;
  /// Predict this object only (it must be lacking in some instance used); all objects if unset.
  std::optional<ObjectKey> object;
};

/// The predicted poses of one object the instances used lack.
struct ObjectPrediction {
  ObjectKey object;
  /// Index of the object in the tree's objects.
  std::size_t object_index = 0;
  /// Names of the ISMs on the object's prediction path, root first.
  std::vector<std::string> path;
  /// The poses, grouped by instance, best instance first.
  std::vector<Pose> poses;
  /// How many of `poses` each instance used contributed (best first): 0 for an instance that
  /// contains the object.
  std::vector<std::size_t> poses_per_instance;
};

/// Predicts where the objects a recognised scene instance lacks are (the paper's Algo. 5 and 6).
/// Built once per tree: the shortest prediction path of every object is found and every relation
/// on a path is inverted and prepared for sampling, so a prediction only draws and chains. A value
/// type that keeps no reference to the tree. One predicted pose of an object starts at the
/// instance's pose (the root ISM's reference pose) and, for every ISM on the object's path, root
/// first, draws one relative pose of the member that leads on (weighted by its step count) and
/// chains its inverse: T <- T * inverse(reference_in_member).
///
/// An instance "contains" an object it matched (similarity > 0). Every other object of the scene
/// is predicted: objects without an estimate and objects present but inconsistent with the
/// instance alike; a contained object never is.
///
/// Random numbers: each (object, instance) pair has its own std::mt19937, seeded through
/// std::seed_seq with (seed, object index, instance rank), so one object's poses do not change
/// when other objects are found, and the result is the same on every platform.
class PosePredictor {
 public:
  /// Throws InputError naming the scene if the tree is inconsistent.
  explicit PosePredictor(const IsmTree& tree);

  const std::string& scene() const { return scene_; }
  const std::vector<ObjectKey>& objects() const { return objects_; }
  const PredictionPath& path(std::size_t object) const { return paths_.at(object); }
  const std::vector<std::string>& pathNames(std::size_t object) const {
    return path_names_.at(object);
  }
  /// Index of an object of the scene; throws InputError naming the object and scene if unknown.
  std::size_t objectIndex(const ObjectKey& key) const;

  /// The objects (indices, in tree order) that `instance` does not contain. Throws InputError if
  /// the instance belongs to another scene.
  std::vector<std::size_t> objectsToPredict(const SceneInstance& instance) const;

  /// `samples` poses of object `object` for a scene instance at `scene_pose`, drawn with the
  /// engine predictionEngine(seed, object, stream).
  std::vector<Pose> predictObject(const Pose& scene_pose, std::size_t object, std::size_t samples,
                                  std::uint32_t seed, std::size_t stream = 0) const;

  /// Predictions from the best options.instances of `instances` (sorted best first, as
  /// TreeRecognizer returns them) for every object some of them lack, in tree order. Throws
  /// InputError if there is no instance, samples or instances is 0, an instance belongs to
  /// another scene, or options.object is unknown or contained in every instance used.
  std::vector<ObjectPrediction> predict(const std::vector<SceneInstance>& instances,
                                        const PredictionOptions& options) const;

 private:
  std::string scene_;
  std::vector<ObjectKey> objects_;
  std::vector<PredictionPath> paths_;
  std::vector<std::vector<std::string>> path_names_;
  /// One sampler per (ISM, member) some path uses; a path's steps as indices into them.
  std::vector<RelationSampler> samplers_;
  std::vector<std::vector<std::size_t>> path_samplers_;  // per object
};

/// The random engine of one (object, instance) stream of a prediction with `seed`.
std::mt19937 predictionEngine(std::uint32_t seed, std::size_t object, std::size_t stream);

}  // namespace asr_pose_prediction
