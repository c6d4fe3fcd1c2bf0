#pragma once

#include <optional>
#include <string>
#include <vector>

#include "asr_ism/common_types.hpp"

namespace asr_ism {

/// The trajectory of one object over the time steps of a demonstration; a step is empty where
/// the object was not observed.
using Trajectory = std::vector<std::optional<Pose>>;

/// A demonstrated scene: the trajectories of its objects over a sequence of time steps (one
/// recorded object configuration per step).
class Demonstration {
 public:
  Demonstration() = default;
  Demonstration(std::string scene, std::vector<ObjectKey> objects);

  const std::string& scene() const { return scene_; }
  const std::vector<ObjectKey>& objects() const { return objects_; }
  std::size_t objectCount() const { return objects_.size(); }
  std::size_t stepCount() const { return steps_.size(); }

  /// Index of an object, or -1 if the demonstration does not contain it.
  int indexOf(const ObjectKey& key) const;

  /// Appends a time step in which no object has been observed yet; returns its index.
  std::size_t addStep();

  /// Sets the pose of object `object` in time step `step`.
  void setPose(std::size_t step, std::size_t object, const Pose& pose);

  const std::optional<Pose>& pose(std::size_t step, std::size_t object) const;

  /// The poses of one object over all time steps.
  Trajectory trajectory(std::size_t object) const;

  /// The objects observed in one time step.
  Configuration configuration(std::size_t step) const;

  /// Throws InputError naming `source` if the demonstration has no object or no step, or if an
  /// object is never observed.
  void validate(const std::string& source) const;

 private:
  std::string scene_;
  std::vector<ObjectKey> objects_;
  std::vector<std::vector<std::optional<Pose>>> steps_;  // [step][object]
};

}  // namespace asr_ism
