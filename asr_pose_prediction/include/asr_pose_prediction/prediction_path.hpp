#pragma once

#include <string>
#include <vector>

#include "asr_ism_tree/ism_tree.hpp"

namespace asr_pose_prediction {

using asr_common::ObjectKey;
using asr_common::Pose;
using asr_ism_tree::IsmTree;

/// One ISM on a prediction path and the member of it that leads on: the placeholder of the next
/// ISM on the path, or, in the last ISM, the object's own leaf.
struct PredictionStep {
  int ism = -1;
  int member = -1;
};

/// The shortest sequence of ISMs from the root to an ISM that has `object` as a leaf (a real
/// member), root first. A pose of the object follows from the root's reference pose by chaining,
/// for every step, the inverse of one of the leading member's relative poses.
struct PredictionPath {
  ObjectKey object;
  std::vector<PredictionStep> steps;
};

/// The prediction path of every object of the tree, in the order of tree.objects(). Found by a
/// breadth-first search from the root, so each object uses its shallowest leaf: an object that is
/// a leaf at two levels is predicted through the upper one, with fewer relations to chain. The
/// search visits a parent's child ISMs in the order of their placeholder members, so among leaves
/// at the same depth the first one reached that way wins (for trees from generateIsmTree: the
/// branch whose placeholder comes first in the root, then first in the next ISM, ...); within an
/// ISM, the first member with the object's key. Throws InputError naming the scene if the tree
/// is inconsistent or an object has no leaf.
std::vector<PredictionPath> shortestPredictionPaths(const IsmTree& tree);

/// The names of the ISMs on a path, root first.
std::vector<std::string> ismNames(const IsmTree& tree, const PredictionPath& path);

}  // namespace asr_pose_prediction
