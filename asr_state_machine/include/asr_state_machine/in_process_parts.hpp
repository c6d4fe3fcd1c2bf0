#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "asr_ism/thread_pool.hpp"
#include "asr_ism_tree/scene_models.hpp"
#include "asr_nbv/next_best_view_planner.hpp"
#include "asr_pose_prediction/pose_predictor.hpp"
#include "asr_robot_model/detection_simulator.hpp"
#include "asr_robot_model/motion_model.hpp"
#include "asr_robot_model/robot_description.hpp"
#include "asr_robot_model/world.hpp"
#include "asr_robot_model/world_map.hpp"
#include "asr_state_machine/parts.hpp"

// The parts of the search on the suite's libraries, in one process: the robot model's motion
// model and simulated detection, ISM-tree recognition, pose prediction, the next-best-view
// planner. Simulated time is what the motion model and the detection simulator say.
namespace asr_state_machine {

/// The simulated robot: it goes where it is told in the time the motion model gives, if its
/// base is free there and the head within its limits.
class SimulatedRobot : public Robot {
 public:
  SimulatedRobot(const asr_robot_model::RobotDescription& robot,
                 const asr_robot_model::WorldMap& map, RobotState start);
  RobotState state() override { return state_; }
  MoveResult moveTo(const RobotState& goal) override;

 private:
  const asr_robot_model::RobotDescription& robot_;
  const asr_robot_model::WorldMap& map_;
  asr_robot_model::MotionSpeeds speeds_;
  RobotState state_;
};

/// The detection simulator (asr_robot_model) behind the Detector interface.
class SimulatedDetector : public Detector {
 public:
  explicit SimulatedDetector(asr_robot_model::DetectionSimulator& simulator)
      : simulator_(simulator) {}
  DetectionResult detect(const Pose& camera, const std::vector<std::string>& types) override;

 private:
  asr_robot_model::DetectionSimulator& simulator_;
};

/// Scene recognition with the ISM trees of the models.
class IsmRecognizer : public Recognizer {
 public:
  explicit IsmRecognizer(const asr_ism_tree::SceneModels& models) : models_(models) {}
  std::map<std::string, std::vector<ObjectKey>> sceneObjects() override;
  std::vector<SceneInstance> recognize(const asr_common::Configuration& found) override;

 private:
  const asr_ism_tree::SceneModels& models_;
};

struct ScenePredictionSettings {
  std::size_t samples = 60;   // poses per missing object and scene
  std::size_t instances = 3;  // best instances of a scene predicted from
};

/// Pose prediction from the recognised instances of each scene (the paper's Algo. 5-6).
class ScenePredictor : public Predictor {
 public:
  ScenePredictor(const asr_ism_tree::SceneModels& models, ScenePredictionSettings settings);
  std::vector<PredictedCloud> predict(const std::vector<SceneInstance>& instances,
                                      const std::vector<ObjectKey>& missing,
                                      std::uint32_t seed) override;

 private:
  std::map<std::string, asr_pose_prediction::PosePredictor> predictors_;
  ScenePredictionSettings settings_;
};

/// The bounding-box search's "prediction": every missing object may be anywhere on the
/// furniture (a grid of poses over every top, random orientations), whatever was found.
class FurniturePredictor : public Predictor {
 public:
  /// `spacing`: metres between grid points.
  FurniturePredictor(const asr_robot_model::World& world, double spacing = 0.25);
  std::vector<PredictedCloud> predict(const std::vector<SceneInstance>& instances,
                                      const std::vector<ObjectKey>& missing,
                                      std::uint32_t seed) override;

 private:
  std::vector<Eigen::Vector3d> points_;
};

/// The next-best-view planner (asr_nbv) with its hypotheses.
class NbvViewPlanner : public ViewPlanner {
 public:
  NbvViewPlanner(const asr_robot_model::RobotDescription& robot,
                 const asr_robot_model::World& world, const asr_robot_model::WorldMap& map,
                 const asr_robot_model::ObjectCatalogue& catalogue,
                 asr_nbv::NbvParameters parameters, asr_ism::ThreadPool* pool, unsigned seed);
  std::size_t setHypotheses(const std::vector<PredictedCloud>& clouds,
                            const std::vector<VisitedView>& visited) override;
  PlannedView next(const RobotState& current) override;
  std::size_t update(const Pose& camera, const std::vector<std::string>& types) override;
  void removeObjects(const std::vector<ObjectKey>& objects) override;

 private:
  const asr_robot_model::WorldMap& map_;
  const asr_robot_model::ObjectCatalogue& catalogue_;
  asr_nbv::NextBestViewPlanner planner_;
  asr_nbv::HypothesisSet hypotheses_;
};

}  // namespace asr_state_machine
