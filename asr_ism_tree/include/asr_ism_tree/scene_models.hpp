#pragma once

#include <memory>
#include <string>
#include <vector>

#include "asr_common/object.hpp"
#include "asr_ism_tree/ism_tree.hpp"
#include "asr_ism_tree/scene_instance.hpp"
#include "asr_ism_tree/tree_recognizer.hpp"

namespace asr_ism_tree {

/// The scene models a recogniser works with: the trees of one or more model files, each with its
/// recogniser built once, so that recognising is all a request costs.
class SceneModels {
 public:
  SceneModels() = default;

  /// Loads every scene of every file, or only `scenes` if not empty. Throws InputError naming the
  /// file or scene for a missing file, a file without models, an unknown scene, or a scene stored
  /// in two files. Nothing is kept if anything fails.
  static SceneModels load(const std::vector<std::string>& model_files,
                          const std::vector<std::string>& scenes = {},
                          const TreeRecognitionParameters& parameters = {});

  std::vector<std::string> scenes() const;
  bool has(const std::string& scene) const;
  /// Throws InputError naming the scene if it is not loaded.
  const IsmTree& tree(const std::string& scene) const;

  /// Instances of `scenes` (all loaded ones if empty) in `configuration`, best confidence first
  /// (ties by scene name, then as each tree ranks them); a scene named twice is answered once.
  /// Throws InputError for a scene not loaded.
  std::vector<SceneInstance> recognize(const asr_common::Configuration& configuration,
                                       const std::vector<std::string>& scenes = {}) const;

 private:
  struct Model {
    std::unique_ptr<IsmTree> tree;  // the recogniser refers to it: keep its address fixed
    std::unique_ptr<TreeRecognizer> recognizer;
  };
  const Model& model(const std::string& scene) const;
  std::vector<Model> models_;
};

}  // namespace asr_ism_tree
