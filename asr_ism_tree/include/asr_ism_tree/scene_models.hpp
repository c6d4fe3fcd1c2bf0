#pragma once

#include <memory>
#include <string>
#include <vector>

#include "asr_common/object.hpp"
#include "asr_ism/thread_pool.hpp"
#include "asr_ism_tree/ism_tree.hpp"
#include "asr_ism_tree/scene_instance.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"

namespace asr_ism_tree {

/// The scene models a recogniser works with: the trees of one or more model files, each with its
/// recogniser built once, so that recognising is all a request costs. Scenes are recognised in
/// parallel on a pool of their own; the answer does not depend on how many threads it has.
class SceneModels {
 public:
  SceneModels() = default;

  /// Loads every scene of every file, or only `scenes` if not empty. Throws InputError naming the
  /// file or scene for a missing file, a file without models, an unknown scene, or a scene stored
  /// in two files. Nothing is kept if anything fails. `threads`: the pool's, counting the caller
  /// (0: one per hardware thread; 1: every scene on the calling thread).
  static SceneModels load(const std::vector<std::string>& model_files,
                          const std::vector<std::string>& scenes = {},
                          const TreeRecognitionParameters& parameters = {}, unsigned threads = 0);

  /// Scene names in load order; the indices below refer to it.
  std::vector<std::string> scenes() const;
  bool has(const std::string& scene) const;
  /// Throws InputError naming the scene if it is not loaded.
  const IsmTree& tree(const std::string& scene) const;
  const IsmTree& tree(std::size_t index) const { return *models_.at(index).tree; }
  const TreeRecognitionParameters& parameters() const { return parameters_; }
  /// How many scenes have an object of `type`: those an estimate of it can change.
  std::size_t scenesWithType(const std::string& type) const;

  /// Instances of `scenes` (all loaded ones if empty) in `configuration`, best confidence first
  /// (ties by scene name, then as each tree ranks them); a scene named twice is answered once.
  /// Throws InputError for a scene not loaded.
  std::vector<SceneInstance> recognize(const asr_common::Configuration& configuration,
                                       const std::vector<std::string>& scenes = {}) const;

  /// Per index of `indices` (into scenes()), that scene's instances in `configuration` as its
  /// tree ranks them. Where recognitions throw, the one of the first such index is rethrown.
  std::vector<std::vector<SceneInstance>> recognizeEach(
      const std::vector<std::size_t>& indices,
      const asr_common::Configuration& configuration) const;

 private:
  struct Model {
    std::unique_ptr<IsmTree> tree;  // the recogniser refers to it: keep its address fixed
    std::unique_ptr<TreeRecognizer> recognizer;
  };
  std::size_t indexOf(const std::string& scene) const;
  std::vector<Model> models_;
  TreeRecognitionParameters parameters_;
  std::unique_ptr<asr_ism::ThreadPool> pool_;  // none: serial
};

/// Best confidence first, ties by scene name, otherwise in the order given (a tree's ranking).
void sortByConfidence(std::vector<SceneInstance>& instances);

}  // namespace asr_ism_tree
