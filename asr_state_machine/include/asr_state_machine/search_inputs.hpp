#pragma once

#include <memory>
#include <string>
#include <vector>

#include "asr_ism_tree/scene_models.hpp"
#include "asr_nbv/nbv_parameters.hpp"
#include "asr_robot_model/robot_description.hpp"
#include "asr_robot_model/world.hpp"
#include "asr_robot_model/world_map.hpp"
#include "asr_state_machine/search_executive.hpp"

namespace asr_state_machine {

/// What one search is asked to do (`asr search`, the search_executive node).
struct SearchRequest {
  std::string world;                     // world file (asr_robot_model's format)
  std::vector<std::string> model_files;  // ISM-tree model databases
  std::vector<std::string> scenes;       // searched scenes; empty: every scene of the models
  std::string demonstrated;              // objects file of demonstrated poses (may be empty)
  std::string catalogue;                 // object catalogue; empty: the shipped one
  SearchConfig config;
  /// Start pose disturbance (bench): metres and radians of seeded uniform noise on x, y and yaw.
  double start_jitter = 0.0;
};

/// The inputs of a search, loaded and checked: whichever parts run the search (in-process or
/// over ROS), the executive's side needs the robot, the world and its map (the direct search),
/// and the models (which objects each scene has).
struct SearchInputs {
  SearchConfig config;
  asr_robot_model::RobotDescription robot;
  asr_robot_model::ObjectCatalogue catalogue;
  asr_robot_model::World world;
  std::unique_ptr<asr_robot_model::WorldMap> map;  // of `world` (which it refers to)
  asr_ism_tree::SceneModels models;
  std::vector<asr_common::ObjectEstimate> demonstrated;
  asr_nbv::NbvParameters nbv;
};

/// Loads and checks every input of `request`, so that bad input (a world, model or scene that
/// does not exist, a required scene no model holds, a time budget that is not positive) fails
/// with asr_common::InputError naming it before anything moves. Heap-allocated: the map refers
/// to the world.
std::unique_ptr<SearchInputs> loadSearchInputs(const SearchRequest& request);

}  // namespace asr_state_machine
