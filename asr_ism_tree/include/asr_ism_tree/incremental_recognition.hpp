#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "asr_common/object.hpp"
#include "asr_ism_tree/scene_instance.hpp"
#include "asr_ism_tree/scene_models.hpp"

namespace asr_ism_tree {

/// Recognition of the configurations a robot sees one after another (the scene_recognizer's
/// continuous mode). A scene is recognised anew only where the estimates it can match (those of
/// its objects' types) changed since the last call, or the models did; the others keep their
/// instances, which are the same: recognition is deterministic and does not depend on estimates
/// a scene cannot match. So an object seen anew costs the scenes that have its type only.
class IncrementalRecognition {
 public:
  /// What models->recognize(configuration) returns (every scene, best first), with the same
  /// errors. After an error nothing is kept: the next call recognises every scene.
  std::vector<SceneInstance> recognize(const std::shared_ptr<const SceneModels>& models,
                                       const asr_common::Configuration& configuration);

  /// How many scenes the last call recognised anew.
  std::size_t scenesRecognizedAnew() const { return recognized_anew_; }

 private:
  std::vector<SceneInstance> recognizeChangedScenes(const asr_common::Configuration& configuration);

  // A scene's last recognition: the estimates it could match (in input order), and its
  // instances with each object's `estimate` an index into those.
  struct SceneResult {
    asr_common::Configuration matchable;
    std::vector<SceneInstance> instances;
    bool recognized = false;
  };
  std::shared_ptr<const SceneModels> models_;
  std::vector<SceneResult> results_;  // per scene of models_
  std::size_t recognized_anew_ = 0;
};

}  // namespace asr_ism_tree
