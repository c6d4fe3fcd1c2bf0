#pragma once

#include <vector>

#include "asr_ism_tree/scene_instance.hpp"

namespace asr_ism_tree {

/// The best instance's confidence, 0 if there is none.
inline double bestConfidence(const std::vector<SceneInstance>& instances) {
  return instances.empty() ? 0.0 : instances.front().confidence;
}

/// The entry of object `key` in an instance, or nullptr.
inline const InstanceObject* find(const SceneInstance& instance, const ObjectKey& key) {
  for (const InstanceObject& object : instance.objects) {
    if (object.key == key)
      return &object;
  }
  return nullptr;
}

}  // namespace asr_ism_tree
