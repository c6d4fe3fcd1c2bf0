#include "asr_ism_tree/scene_models.hpp"

#include <algorithm>
#include <exception>

#include "asr_common/input_error.hpp"
#include "asr_ism_tree/sqlite/model_store.hpp"

namespace asr_ism_tree {

using asr_common::InputError;

SceneModels SceneModels::load(const std::vector<std::string>& model_files,
                              const std::vector<std::string>& scenes,
                              const TreeRecognitionParameters& parameters, unsigned threads) {
  if (model_files.empty())
    throw InputError("no model file given");
  SceneModels loaded;
  loaded.parameters_ = parameters;
  // Recognitions of several scenes share it; a single scene's recogniser uses it for the ISMs of
  // a tree level (a parallelFor issued from inside a task runs serially, so they never wait).
  if (threads != 1)
    loaded.pool_ = std::make_unique<asr_ism::ThreadPool>(threads);
  std::vector<std::string> sources;  // the file of each loaded scene
  for (const std::string& file : model_files) {
    const std::vector<std::string> stored = sqlite::listModelScenes(file);
    if (stored.empty())
      throw InputError(file + " holds no scene model");
    for (const std::string& scene : stored) {
      if (!scenes.empty() && std::find(scenes.begin(), scenes.end(), scene) == scenes.end())
        continue;
      if (loaded.has(scene)) {
        throw InputError("scene '" + scene + "' is stored in both " +
                         sources[loaded.indexOf(scene)] + " and " + file);
      }
      Model model;
      model.tree = std::make_unique<IsmTree>(sqlite::loadIsmTree(file, scene));
      model.recognizer =
          std::make_unique<TreeRecognizer>(*model.tree, parameters, loaded.pool_.get());
      loaded.models_.push_back(std::move(model));
      sources.push_back(file);
    }
  }
  for (const std::string& scene : scenes) {
    if (!loaded.has(scene))
      throw InputError("scene '" + scene + "' is in none of the model files");
  }
  return loaded;
}

std::vector<std::string> SceneModels::scenes() const {
  std::vector<std::string> names;
  for (const Model& model : models_)
    names.push_back(model.tree->scene);
  return names;
}

bool SceneModels::has(const std::string& scene) const {
  return std::any_of(models_.begin(), models_.end(),
                     [&](const Model& model) { return model.tree->scene == scene; });
}

std::size_t SceneModels::indexOf(const std::string& scene) const {
  for (std::size_t index = 0; index < models_.size(); ++index) {
    if (models_[index].tree->scene == scene)
      return index;
  }
  throw InputError("scene '" + scene + "' is not loaded");
}

const IsmTree& SceneModels::tree(const std::string& scene) const {
  return *models_[indexOf(scene)].tree;
}

std::size_t SceneModels::scenesWithType(const std::string& type) const {
  return static_cast<std::size_t>(
      std::count_if(models_.begin(), models_.end(), [&](const Model& model) {
        const auto& objects = model.tree->objects();
        return std::any_of(objects.begin(), objects.end(),
                           [&](const ObjectKey& key) { return key.type == type; });
      }));
}

std::vector<SceneInstance> SceneModels::recognize(const asr_common::Configuration& configuration,
                                                  const std::vector<std::string>& scenes) const {
  std::vector<std::size_t> wanted;
  if (scenes.empty()) {
    for (std::size_t index = 0; index < models_.size(); ++index)
      wanted.push_back(index);
  } else {
    for (const std::string& scene : scenes) {
      // A scene asked for twice is answered once.
      const std::size_t asked = indexOf(scene);
      if (std::find(wanted.begin(), wanted.end(), asked) == wanted.end())
        wanted.push_back(asked);
    }
  }
  std::vector<SceneInstance> instances;
  for (std::vector<SceneInstance>& found : recognizeEach(wanted, configuration)) {
    instances.insert(instances.end(), std::make_move_iterator(found.begin()),
                     std::make_move_iterator(found.end()));
  }
  sortByConfidence(instances);
  return instances;
}

std::vector<std::vector<SceneInstance>> SceneModels::recognizeEach(
    const std::vector<std::size_t>& indices, const asr_common::Configuration& configuration) const {
  for (std::size_t index : indices)
    models_.at(index);  // throws before any work for an index out of range
  std::vector<std::vector<SceneInstance>> found(indices.size());
  // Caught per scene, so that which error is reported does not depend on the threads' timing.
  std::vector<std::exception_ptr> errors(indices.size());
  const auto recognizeOne = [&](std::size_t i) {
    try {
      found[i] = models_[indices[i]].recognizer->recognize(configuration);
    } catch (...) {
      errors[i] = std::current_exception();
    }
  };
  if (pool_ != nullptr && indices.size() > 1) {
    pool_->parallelFor(indices.size(), recognizeOne);
  } else {
    for (std::size_t i = 0; i < indices.size(); ++i)
      recognizeOne(i);
  }
  for (const std::exception_ptr& error : errors) {
    if (error)
      std::rethrow_exception(error);
  }
  return found;
}

void sortByConfidence(std::vector<SceneInstance>& instances) {
  std::stable_sort(instances.begin(), instances.end(),
                   [](const SceneInstance& a, const SceneInstance& b) {
                     if (a.confidence != b.confidence)
                       return a.confidence > b.confidence;
                     return a.scene < b.scene;
                   });
}

}  // namespace asr_ism_tree
