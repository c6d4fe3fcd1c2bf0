#pragma once

#include <string>
#include <vector>

#include "asr_common/object.hpp"

namespace asr_ism_tree {

using asr_common::ObjectKey;
using asr_common::Pose;

/// How a scene object present in the input fits an instance. An object that appears in several
/// ISMs of the tree (as in a complete topology) is rated once per appearance; `similarity` is the
/// mean over its appearances of its contribution to the root's objective (0 where it was not
/// matched), the compliances are the means over the appearances where it was matched.
struct InstanceObject {
  ObjectKey key;
  Pose pose;                // of the input estimate
  int estimate = -1;        // index in the recognised configuration
  double similarity = 0.0;  // in [0, 1]; 0: present but inconsistent with this instance
  double position_compliance = 0.0;
  double orientation_compliance = 0.0;
  int appearances = 0;  // leaves of the tree that stand for this object
};

/// One ISM's share of an instance.
struct InstanceIsm {
  std::string name;
  double objective = 0.0;  // 0 if the ISM has no result in this instance
  Pose reference_pose;     // meaningful only if `recognized`
  bool recognized = false;
};

/// An instance of a scene category found in a configuration.
struct SceneInstance {
  std::string scene;
  /// The paper's confidence: root objective / number of leaves of the tree, in [0, 1]. An object
  /// counts once per leaf it appears in, so what one object is worth depends on the topology.
  double confidence = 0.0;
  /// The mean over the scene's objects of their `similarity` (missing objects count 0), in
  /// [0, 1]: 6 of 8 objects in place give 0.75 whatever the topology.
  double object_confidence = 0.0;
  /// True if some estimate was matched by type only: it had no id, or one the model does not
  /// know for its type (see TreeRecognizer).
  bool ids_ignored = false;
  /// True if every search of the recognition that found this instance completed within its work
  /// limits: then no instance of the scene in those estimates scores higher than the best one
  /// returned (its confidence is that of the exhaustive search, every estimate entering and
  /// every sub-ISM passing every result up). False: a search ran out (or was switched off) and
  /// the best confidence is a lower bound of the exhaustive one (TreeRecognitionStats says
  /// which search ran out).
  bool search_complete = false;
  /// The root ISM's reference pose.
  Pose pose;
  /// Scene objects present in the input, in the order of the tree's objects.
  std::vector<InstanceObject> objects;
  /// Scene objects without any estimate in the input.
  std::vector<ObjectKey> missing;
  /// Every ISM of the tree, in tree order (root first).
  std::vector<InstanceIsm> isms;
};

}  // namespace asr_ism_tree
