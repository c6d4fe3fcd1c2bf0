#pragma once

#include <string>
#include <vector>

#include "asr_ism/ism.hpp"
#include "asr_ism/ism_recognizer.hpp"
#include "asr_ism_tree/relation_topology.hpp"

namespace asr_ism_tree {

/// A scene model: ISMs linked into a tree. isms[0] is the root, named after the scene; a sub-ISM
/// `<scene>_sub<k>` sits at isms[k + 1]. The hierarchy is explicit: `parent` and `level` per ISM,
/// and every placeholder member names its child ISM.
struct IsmTree {
  std::string scene;
  std::vector<asr_ism::Ism> isms;
  std::vector<int> parent;  // per ISM, -1 for the root
  std::vector<int> level;   // per ISM, 0 for the root
  /// The relations the tree models (over the scene's real objects).
  RelationTopology topology;
  /// Bin size and angle threshold the tree was learned for.
  asr_ism::IsmRecognitionParameters parameters;

  const std::vector<ObjectKey>& objects() const { return topology.objects(); }
  /// Number of ISM levels (1 for a single ISM).
  int height() const;
  /// Number of real-object members over all ISMs: the highest objective the root can reach,
  /// since an object that appears in several ISMs counts once per appearance.
  std::size_t leafCount() const;
  std::size_t relativePoseCount() const;
  /// Index of the ISM with this name, or -1.
  int indexOf(const std::string& ism_name) const;
  /// The member of `parent[ism]` that stands for ISM `ism`.
  int placeholderMemberInParent(int ism) const;

  /// Throws InputError naming `what` if the links are inconsistent (a loaded model was edited), or
  /// if validateExtent does.
  void validate(const std::string& what) const;
  /// Throws InputError naming `what` if the parameters are outside input_limits.hpp, a relation is
  /// longer than kMaxRelationLength, or votes could land beyond the voting space.
  void validateExtent(const std::string& what) const;
};

}  // namespace asr_ism_tree
