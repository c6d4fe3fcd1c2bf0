#pragma once

#include <cstddef>
#include <vector>

#include "asr_ism/ism_recognizer.hpp"
#include "asr_ism/thread_pool.hpp"
#include "asr_ism_tree/ism_tree.hpp"
#include "asr_ism_tree/scene_instance.hpp"

namespace asr_ism_tree {

struct TreeRecognitionParameters {
  /// How many of a sub-ISM's best results are passed up to its parent as placeholder estimates.
  /// The cap keeps the combinations in the parent from exploding; results of one ISM that match
  /// the same inputs are merged before the cap, so several distinct hypotheses get through.
  std::size_t results_passed_up = 4;
};

struct TreeRecognitionStats {
  asr_ism::IsmRecognitionStats isms;  // summed over the tree's ISMs
  std::size_t root_results = 0;
};

/// Recognises the scene a tree models (the paper's Algo. 2-4). ISMs are evaluated bottom-up, level
/// by level; the best results of each sub-ISM become placeholder estimates of its parent, weighted
/// by their objective. Every result of the root is then assembled top-down, following the
/// explicit links from placeholder matches to the child results they came from, into a scene
/// instance. The ISMs of one level run in parallel on the pool. Every input carries the real
/// estimates it stands for, so the root drops results whose estimates are a subset of a better
/// result's: each instance found uses some estimate that no better instance uses.
/// The input order does not matter (estimates are sorted first); the output is deterministic
/// whatever the pool's size. Clutter (objects the scene does not know) is ignored.
class TreeRecognizer {
 public:
  /// The tree (and the pool, if given) must outlive the recognizer.
  explicit TreeRecognizer(const IsmTree& tree, TreeRecognitionParameters parameters = {},
                          asr_ism::ThreadPool* pool = nullptr);

  /// Instances sorted by confidence, best first. Throws InputError for a non-finite pose.
  std::vector<SceneInstance> recognize(const asr_common::Configuration& configuration,
                                       TreeRecognitionStats* stats = nullptr) const;

  const IsmTree& tree() const { return tree_; }

 private:
  struct Leaf {
    int ism;
    int member;
    int object;  // index in tree.objects()
  };

  const IsmTree& tree_;
  TreeRecognitionParameters parameters_;
  asr_ism::ThreadPool* pool_;
  std::vector<std::vector<int>> levels_;  // ISM indices per level, deepest level first
  std::vector<Leaf> leaves_;
};

}  // namespace asr_ism_tree
