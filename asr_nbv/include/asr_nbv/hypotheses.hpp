#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "asr_common/object.hpp"
#include "asr_common/pose.hpp"
#include "asr_robot_model/world.hpp"

namespace asr_nbv {

/// The predicted poses of one object (a PredictedPoseCloud, or one entry of
/// `asr ism predict --json`), as given: they are validated when hypotheses are made of them.
struct PredictedCloud {
  asr_common::ObjectKey key;
  std::vector<asr_common::Pose> poses;
};

/// One predicted pose of an object: where it may be, the box it would fill (so its own voxels
/// do not hide it) and the directions it can be recognised from, in map, each active until a
/// view has looked from it.
struct Hypothesis {
  asr_common::ObjectKey key;
  int type = 0;  // index into HypothesisSet::types()
  asr_robot_model::Box box;
  /// Unit, in map. Empty: recognisable from every side, and `active` has a single entry.
  std::vector<Eigen::Vector3d> normals;
  std::vector<char> active;
  int active_count = 0;

  bool counts() const { return active_count > 0; }
};

/// Size of a type the catalogue does not know (a box of this edge).
inline constexpr double kUnknownTypeSize = 0.1;

/// The hypotheses of a search: made from predicted clouds and the object catalogue, updated
/// after each view, objects removed once found, and reset to how they were made.
class HypothesisSet {
 public:
  HypothesisSet() = default;
  /// Poses that are not finite or whose quaternion is far from unit length are rejected and
  /// counted (rejectedPoses()); a type without catalogue entry is recognisable from every side
  /// with a kUnknownTypeSize box, and a warning names it.
  HypothesisSet(const std::vector<PredictedCloud>& clouds,
                const asr_robot_model::ObjectCatalogue& catalogue);

  const std::vector<Hypothesis>& hypotheses() const { return hypotheses_; }
  std::vector<Hypothesis>& hypotheses() { return hypotheses_; }
  /// Every type of the clouds, sorted.
  const std::vector<std::string>& types() const { return types_; }
  /// Index into types(), -1 if there is no such type.
  int typeIndex(const std::string& type) const;

  int rejectedPoses() const { return rejected_poses_; }
  const std::vector<std::string>& warnings() const { return warnings_; }

  /// Hypotheses that still count (an active normal, object not removed).
  std::size_t countingHypotheses() const;
  /// Types with a hypothesis that counts.
  std::size_t countingTypes() const;

  /// Removes the hypotheses of these objects (an empty id removes every object of the type);
  /// returns how many were removed.
  std::size_t removeObjects(const std::vector<asr_common::ObjectKey>& objects);
  /// Back to the hypotheses as made: every normal active, nothing removed.
  void reset();

 private:
  std::vector<Hypothesis> made_;
  std::vector<Hypothesis> hypotheses_;
  std::vector<std::string> types_;
  int rejected_poses_ = 0;
  std::vector<std::string> warnings_;
};

}  // namespace asr_nbv
