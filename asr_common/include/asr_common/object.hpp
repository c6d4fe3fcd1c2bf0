#pragma once

#include <string>
#include <tuple>
#include <vector>

#include "asr_common/pose.hpp"

namespace asr_common {

/// Identifies an object: its type (class label) and its instance id, which tells apart several
/// objects of one type (the original recordings call it observedId).
struct ObjectKey {
  std::string type;
  std::string id;

  /// "type:id", or "type" when the id is empty.
  std::string toString() const;

  friend bool operator==(const ObjectKey& a, const ObjectKey& b) {
    return a.type == b.type && a.id == b.id;
  }
  friend bool operator!=(const ObjectKey& a, const ObjectKey& b) { return !(a == b); }
  friend bool operator<(const ObjectKey& a, const ObjectKey& b) {
    return std::tie(a.type, a.id) < std::tie(b.type, b.id);
  }
};

/// One 6-DoF estimate of an object, as a detector or a recording reports it.
struct ObjectEstimate {
  ObjectKey key;
  Pose pose;
};

/// A set of object estimates observed together (one time step, or one camera view's worth).
using Configuration = std::vector<ObjectEstimate>;

/// The estimates' poses, each validated and canonicalised (validatedPose); throws InputError
/// naming the first estimate that fails ("object estimate <index> (<key>)").
std::vector<Pose> validatedPoses(const Configuration& configuration);

}  // namespace asr_common
