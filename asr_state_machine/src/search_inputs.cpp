#include "asr_state_machine/search_inputs.hpp"

#include <fstream>

#include "asr_common/input_error.hpp"
#include "asr_ism/configuration_file.hpp"

namespace asr_state_machine {

namespace {

void requireFile(const std::string& path, const std::string& what) {
  if (path.empty())
    throw asr_common::InputError(what + ": no file given");
  if (!std::ifstream(path).good()) {
    throw asr_common::InputError(what + " '" + path + "' does not exist or cannot be read");
  }
}

void checkRequiredScenes(const SearchRequest& request, const asr_ism_tree::SceneModels& models) {
  for (const auto& [scene, threshold] : request.config.required_scenes) {
    if (!models.has(scene)) {
      throw asr_common::InputError("required scene '" + scene + "' is in none of the models" +
                                   (request.scenes.empty() ? "" : " searched"));
    }
    if (!(threshold >= 0.0 && threshold <= 1.0)) {
      throw asr_common::InputError("the confidence required of scene '" + scene +
                                   "' must lie in [0, 1]");
    }
  }
}

}  // namespace

std::unique_ptr<SearchInputs> loadSearchInputs(const SearchRequest& request) {
  auto inputs = std::make_unique<SearchInputs>();
  SearchInputs& s = *inputs;
  s.config = request.config;
  requireFile(request.world, "world");
  if (request.model_files.empty())
    throw asr_common::InputError("no model file given");
  for (const std::string& file : request.model_files)
    requireFile(file, "model file");
  if (!(s.config.max_sim_seconds > 0.0)) {
    throw asr_common::InputError("the time budget must be a positive number of seconds");
  }
  s.robot = asr_robot_model::loadRobotDescription(asr_robot_model::defaultRobotUrdf());
  s.catalogue = asr_robot_model::loadObjectCatalogue(
      request.catalogue.empty() ? asr_robot_model::defaultObjectCatalogue() : request.catalogue);
  s.world = asr_robot_model::loadWorld(request.world, s.catalogue);
  s.models = asr_ism_tree::SceneModels::load(request.model_files, request.scenes);
  checkRequiredScenes(request, s.models);
  if (!request.demonstrated.empty())
    s.demonstrated = asr_ism::readConfigurationFile(request.demonstrated);
  s.nbv = asr_nbv::loadNbvParameters(asr_nbv::defaultNbvParameters());
  s.map = std::make_unique<asr_robot_model::WorldMap>(s.world, s.nbv.occlusion_resolution,
                                                      s.robot.base_radius);
  return inputs;
}

}  // namespace asr_state_machine
