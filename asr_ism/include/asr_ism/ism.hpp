#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "asr_ism/common_types.hpp"

namespace asr_ism {

/// One learned relative pose: where the ISM's reference is, seen from a member object. Time
/// steps with the same relative pose are stored once; `step_count` says how many there were.
struct RelativePose {
  Pose reference_in_member;
  std::uint32_t step_count = 1;
};

/// An object an ISM relates to its reference: either a real object (a leaf of an ISM tree) or the
/// placeholder reference object of a child ISM, whose estimates are that ISM's results.
struct IsmMember {
  /// Leaf: the object's key. Placeholder: {child ISM name, ""}.
  ObjectKey object;
  /// Index of the child ISM in its tree for a placeholder, -1 for a real object.
  int child_ism = -1;
  std::vector<RelativePose> relative_poses;

  bool isPlaceholder() const { return child_ism >= 0; }
};

/// One Implicit Shape Model: a star of relations between a reference object (the star's centre,
/// which is itself a member and votes with the identity) and the other members.
struct Ism {
  std::string name;
  /// The real object whose trajectory defines the reference pose.
  ObjectKey reference;
  std::vector<IsmMember> members;

  std::size_t relativePoseCount() const;
};

}  // namespace asr_ism
