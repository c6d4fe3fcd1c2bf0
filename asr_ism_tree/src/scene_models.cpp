#include "asr_ism_tree/scene_models.hpp"

#include <algorithm>

#include "asr_common/input_error.hpp"
#include "asr_ism_tree/sqlite/model_store.hpp"

namespace asr_ism_tree {

using asr_common::InputError;

SceneModels SceneModels::load(const std::vector<std::string>& model_files,
                              const std::vector<std::string>& scenes,
                              const TreeRecognitionParameters& parameters) {
  if (model_files.empty())
    throw InputError("no model file given");
  SceneModels loaded;
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
                         sources[&loaded.model(scene) - loaded.models_.data()] + " and " + file);
      }
      Model model;
      model.tree = std::make_unique<IsmTree>(sqlite::loadIsmTree(file, scene));
      model.recognizer = std::make_unique<TreeRecognizer>(*model.tree, parameters);
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

const SceneModels::Model& SceneModels::model(const std::string& scene) const {
  for (const Model& model : models_) {
    if (model.tree->scene == scene)
      return model;
  }
  throw InputError("scene '" + scene + "' is not loaded");
}

const IsmTree& SceneModels::tree(const std::string& scene) const {
  return *model(scene).tree;
}

std::vector<SceneInstance> SceneModels::recognize(const asr_common::Configuration& configuration,
                                                  const std::vector<std::string>& scenes) const {
  std::vector<const Model*> wanted;
  if (scenes.empty()) {
    for (const Model& model : models_)
      wanted.push_back(&model);
  } else {
    for (const std::string& scene : scenes) {
      // A scene asked for twice is answered once.
      const Model* asked = &model(scene);
      if (std::find(wanted.begin(), wanted.end(), asked) == wanted.end())
        wanted.push_back(asked);
    }
  }
  std::vector<SceneInstance> instances;
  for (const Model* model : wanted) {
    std::vector<SceneInstance> found = model->recognizer->recognize(configuration);
    instances.insert(instances.end(), std::make_move_iterator(found.begin()),
                     std::make_move_iterator(found.end()));
  }
  std::stable_sort(instances.begin(), instances.end(),
                   [](const SceneInstance& a, const SceneInstance& b) {
                     if (a.confidence != b.confidence)
                       return a.confidence > b.confidence;
                     return a.scene < b.scene;
                   });
  return instances;
}

}  // namespace asr_ism_tree
