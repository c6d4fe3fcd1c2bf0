#include "asr_state_machine/in_process_search.hpp"

#include <random>

#include "asr_ism/thread_pool.hpp"
#include "asr_robot_model/detection_simulator.hpp"
#include "asr_state_machine/furniture_sweep.hpp"
#include "asr_state_machine/in_process_parts.hpp"

namespace asr_state_machine {

namespace {

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
  std::unique_ptr<SearchInputs> inputs;
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
  s.inputs = loadSearchInputs(request);
  const SearchInputs& in = *s.inputs;
  asr_robot_model::DetectionSettings detection;
  detection.frustum = in.nbv.frustum;
  detection.position_sigma = 0.005;
  detection.angle_sigma = 0.02;
  s.simulator = std::make_unique<asr_robot_model::DetectionSimulator>(in.world, *in.map, detection,
                                                                      in.config.seed);
  const RobotState start =
      jitteredStart(in.world.robot, request.start_jitter, in.config.seed, *in.map);
  s.simulated_robot = std::make_unique<SimulatedRobot>(in.robot, *in.map, start);
  s.detector = std::make_unique<SimulatedDetector>(*s.simulator);
  s.recognizer = std::make_unique<IsmRecognizer>(in.models);
  if (in.config.mode == SearchMode::kBoundingBox) {
    s.predictor = std::make_unique<FurniturePredictor>(in.world);
  } else {
    s.predictor = std::make_unique<ScenePredictor>(in.models, ScenePredictionSettings{});
  }
  s.view_planner = std::make_unique<NbvViewPlanner>(in.robot, in.world, *in.map, in.catalogue,
                                                    in.nbv, &s.pool, in.config.seed);
  s.direct_search = std::make_unique<FurnitureSweep>(in.robot, in.world, *in.map, in.nbv.frustum,
                                                     in.demonstrated);
}

InProcessSearch::~InProcessSearch() = default;

SearchResult InProcessSearch::run() {
  Setup& s = *setup_;
  SearchExecutive executive({*s.simulated_robot, *s.detector, *s.recognizer, *s.predictor,
                             *s.view_planner, *s.direct_search},
                            s.inputs->config);
  return executive.run();
}

}  // namespace asr_state_machine
