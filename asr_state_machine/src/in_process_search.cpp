#include "asr_state_machine/in_process_search.hpp"

#include <fstream>
#include <optional>
#include <random>
#include <set>

#include "asr_common/input_error.hpp"
#include "asr_ism/configuration_file.hpp"
#include "asr_ism/thread_pool.hpp"
#include "asr_ism_tree/scene_models.hpp"
#include "asr_nbv/nbv_parameters.hpp"
#include "asr_robot_model/detection_simulator.hpp"
#include "asr_robot_model/robot_description.hpp"
#include "asr_robot_model/world.hpp"
#include "asr_robot_model/world_map.hpp"
#include "asr_state_machine/furniture_sweep.hpp"
#include "asr_state_machine/in_process_parts.hpp"

namespace asr_state_machine {

namespace {

void requireFile(const std::string& path, const std::string& what) {
  if (path.empty())
    throw asr_common::InputError(what + ": no file given");
  if (!std::ifstream(path).good()) {
    throw asr_common::InputError(what + " '" + path + "' does not exist or cannot be read");
  }
}

RobotState jitteredStart(RobotState start, double jitter, std::uint32_t seed,
                         const asr_robot_model::WorldMap& map) {
  if (jitter <= 0.0)
    return start;
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-jitter, jitter);
  for (int attempt = 0; attempt < 100; ++attempt) {
    RobotState moved = start;
    moved.x += offset(random);
    moved.y += offset(random);
    moved.yaw = asr_robot_model::wrapAngle(moved.yaw + 3.0 * offset(random));
    if (map.baseIsFree(moved.x, moved.y))
      return moved;
  }
  return start;
}

}  // namespace

struct InProcessSearch::Setup {
  SearchConfig config;
  asr_robot_model::RobotDescription robot;
  asr_robot_model::ObjectCatalogue catalogue;
  asr_robot_model::World world;
  std::unique_ptr<asr_robot_model::WorldMap> map;
  asr_ism_tree::SceneModels models;
  asr_ism::ThreadPool pool{0};
  std::unique_ptr<asr_robot_model::DetectionSimulator> simulator;
  std::unique_ptr<SimulatedRobot> simulated_robot;
  std::unique_ptr<SimulatedDetector> detector;
  std::unique_ptr<IsmRecognizer> recognizer;
  std::unique_ptr<Predictor> predictor;
  std::unique_ptr<NbvViewPlanner> view_planner;
  std::unique_ptr<FurnitureSweep> direct_search;
};

InProcessSearch::InProcessSearch(const SearchRequest& request) : setup_(std::make_unique<Setup>()) {
  Setup& s = *setup_;
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
  for (const auto& [scene, threshold] : s.config.required_scenes) {
    if (!s.models.has(scene)) {
      throw asr_common::InputError("required scene '" + scene + "' is in none of the models" +
                                   (request.scenes.empty() ? "" : " searched"));
    }
    if (!(threshold >= 0.0 && threshold <= 1.0)) {
      throw asr_common::InputError("the confidence required of scene '" + scene +
                                   "' must lie in [0, 1]");
    }
  }
  std::vector<asr_common::ObjectEstimate> demonstrated;
  if (!request.demonstrated.empty()) {
    demonstrated = asr_ism::readConfigurationFile(request.demonstrated);
  }

  const asr_nbv::NbvParameters nbv = asr_nbv::loadNbvParameters(asr_nbv::defaultNbvParameters());
  s.map = std::make_unique<asr_robot_model::WorldMap>(s.world, nbv.occlusion_resolution,
                                                      s.robot.base_radius);
  asr_robot_model::DetectionSettings detection;
  detection.frustum = nbv.frustum;
  detection.position_sigma = 0.005;
  detection.angle_sigma = 0.02;
  s.simulator = std::make_unique<asr_robot_model::DetectionSimulator>(s.world, *s.map, detection,
                                                                      s.config.seed);
  const RobotState start =
      jitteredStart(s.world.robot, request.start_jitter, s.config.seed, *s.map);
  s.simulated_robot = std::make_unique<SimulatedRobot>(s.robot, *s.map, start);
  s.detector = std::make_unique<SimulatedDetector>(*s.simulator);
  s.recognizer = std::make_unique<IsmRecognizer>(s.models);
  if (s.config.mode == SearchMode::kBoundingBox) {
    s.predictor = std::make_unique<FurniturePredictor>(s.world);
  } else {
    s.predictor = std::make_unique<ScenePredictor>(s.models, ScenePredictionSettings{});
  }
  s.view_planner = std::make_unique<NbvViewPlanner>(s.robot, s.world, *s.map, s.catalogue, nbv,
                                                    &s.pool, s.config.seed);
  s.direct_search =
      std::make_unique<FurnitureSweep>(s.robot, s.world, *s.map, nbv.frustum, demonstrated);
}

InProcessSearch::~InProcessSearch() = default;

SearchResult InProcessSearch::run() {
  Setup& s = *setup_;
  SearchExecutive executive({*s.simulated_robot, *s.detector, *s.recognizer, *s.predictor,
                             *s.view_planner, *s.direct_search},
                            s.config);
  return executive.run();
}

}  // namespace asr_state_machine
