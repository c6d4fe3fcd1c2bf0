#include "asr_state_machine/in_process_parts.hpp"

#include <algorithm>
#include <random>
#include <set>

#include "asr_common/input_error.hpp"
#include "asr_nbv/view_rating.hpp"
#include "asr_robot_model/forward_kinematics.hpp"

namespace asr_state_machine {

SimulatedRobot::SimulatedRobot(const asr_robot_model::RobotDescription& robot,
                               const asr_robot_model::WorldMap& map, RobotState start)
    : robot_(robot), map_(map), speeds_(asr_robot_model::speedsOf(robot)), state_(start) {}

MoveResult SimulatedRobot::moveTo(const RobotState& goal) {
  const std::string where = "(" + std::to_string(goal.x) + ", " + std::to_string(goal.y) + ")";
  if (!std::isfinite(goal.x) || !std::isfinite(goal.y) || !std::isfinite(goal.yaw) ||
      !std::isfinite(goal.pan) || !std::isfinite(goal.tilt)) {
    throw PartFailure("robot", "goal state is not finite");
  }
  if (!map_.baseIsFree(goal.x, goal.y)) {
    throw PartFailure("robot", "the base cannot stand at " + where);
  }
  if (!robot_.pan.withinLimits(goal.pan) || !robot_.tilt.withinLimits(goal.tilt)) {
    throw PartFailure("robot", "pan or tilt of the goal at " + where + " is beyond its limits");
  }
  MoveResult result;
  result.seconds = asr_robot_model::motionBetween(state_, goal, speeds_).seconds;
  state_ = goal;
  result.reached = goal;
  result.camera = asr_robot_model::cameraPose(robot_, goal);
  return result;
}

DetectionResult SimulatedDetector::detect(const Pose& camera,
                                          const std::vector<std::string>& types) {
  const asr_robot_model::Detections detections = simulator_.detect(camera, types);
  return {detections.detected, detections.seconds};
}

std::map<std::string, std::vector<ObjectKey>> IsmRecognizer::sceneObjects() {
  std::map<std::string, std::vector<ObjectKey>> objects;
  for (const std::string& scene : models_.scenes())
    objects[scene] = models_.tree(scene).objects();
  return objects;
}

std::vector<SceneInstance> IsmRecognizer::recognize(const asr_common::Configuration& found) {
  try {
    return models_.recognize(found);
  } catch (const asr_common::InputError& error) {
    throw PartFailure("scene_recognizer", error.what());
  }
}

ScenePredictor::ScenePredictor(const asr_ism_tree::SceneModels& models,
                               ScenePredictionSettings settings)
    : settings_(settings) {
  for (const std::string& scene : models.scenes()) {
    predictors_.emplace(scene, asr_pose_prediction::PosePredictor(models.tree(scene)));
  }
}

std::vector<PredictedCloud> ScenePredictor::predict(const std::vector<SceneInstance>& instances,
                                                    const std::vector<ObjectKey>& missing,
                                                    std::uint32_t seed) {
  std::map<ObjectKey, PredictedCloud> clouds;
  for (const auto& [scene, predictor] : predictors_) {
    std::vector<SceneInstance> of_scene;
    for (const SceneInstance& instance : instances) {
      if (instance.scene == scene)
        of_scene.push_back(instance);
    }
    if (of_scene.empty())
      continue;
    asr_pose_prediction::PredictionOptions options;
    options.samples = settings_.samples;
    options.instances = std::min(settings_.instances, of_scene.size());
    options.seed = seed;
    try {
      for (const auto& prediction : predictor.predict(of_scene, options)) {
        if (std::find(missing.begin(), missing.end(), prediction.object) == missing.end())
          continue;
        PredictedCloud& cloud = clouds[prediction.object];
        cloud.key = prediction.object;
        cloud.poses.insert(cloud.poses.end(), prediction.poses.begin(), prediction.poses.end());
      }
    } catch (const asr_common::InputError& error) {
      throw PartFailure("pose_predictor", error.what());
    }
  }
  std::vector<PredictedCloud> result;
  for (auto& [key, cloud] : clouds)
    result.push_back(std::move(cloud));
  return result;
}

FurniturePredictor::FurniturePredictor(const asr_robot_model::World& world, double spacing) {
  for (const asr_robot_model::Furniture& furniture : world.furniture) {
    const asr_robot_model::Box& box = furniture.box;
    const int nx = std::max(1, static_cast<int>(box.size.x() / spacing));
    const int ny = std::max(1, static_cast<int>(box.size.y() / spacing));
    for (int i = 0; i < nx; ++i) {
      for (int j = 0; j < ny; ++j) {
        // Cell centres on the top, a small object's half height above it.
        const Eigen::Vector3d local((i + 0.5) * box.size.x() / nx - box.size.x() / 2,
                                    (j + 0.5) * box.size.y() / ny - box.size.y() / 2,
                                    box.size.z() / 2 + 0.08);
        points_.push_back(box.pose.position + box.pose.orientation * local);
      }
    }
  }
}

std::vector<PredictedCloud> FurniturePredictor::predict(const std::vector<SceneInstance>&,
                                                        const std::vector<ObjectKey>& missing,
                                                        std::uint32_t seed) {
  // Without scene knowledge an object may stand in any orientation: uniform random rotations
  // (normalised Gaussian 4-vectors), so that its recognisable sides point every way.
  std::mt19937 random(seed);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  std::vector<PredictedCloud> clouds;
  for (const ObjectKey& key : missing) {
    PredictedCloud cloud;
    cloud.key = key;
    for (const Eigen::Vector3d& point : points_) {
      const Eigen::Quaterniond rotation(gaussian(random), gaussian(random), gaussian(random),
                                        gaussian(random));
      cloud.poses.emplace_back(point, asr_common::canonicalQuaternion(rotation));
    }
    clouds.push_back(std::move(cloud));
  }
  return clouds;
}

NbvViewPlanner::NbvViewPlanner(const asr_robot_model::RobotDescription& robot,
                               const asr_robot_model::World& world,
                               const asr_robot_model::WorldMap& map,
                               const asr_robot_model::ObjectCatalogue& catalogue,
                               asr_nbv::NbvParameters parameters, asr_ism::ThreadPool* pool,
                               unsigned seed)
    : map_(map), catalogue_(catalogue), planner_(robot, world, map, parameters, pool, seed) {}

std::size_t NbvViewPlanner::setHypotheses(const std::vector<PredictedCloud>& clouds,
                                          const std::vector<VisitedView>& visited) {
  hypotheses_ = asr_nbv::HypothesisSet(clouds, catalogue_);
  for (const VisitedView& view : visited) {
    asr_nbv::updateAfterView(hypotheses_, view.camera, view.types, planner_.parameters(), &map_);
  }
  return hypotheses_.countingHypotheses();
}

PlannedView NbvViewPlanner::next(const RobotState& current) {
  try {
    return planner_.plan(hypotheses_, current);
  } catch (const asr_common::InputError& error) {
    throw PartFailure("next_best_view", error.what());
  }
}

std::size_t NbvViewPlanner::update(const Pose& camera, const std::vector<std::string>& types) {
  return asr_nbv::updateAfterView(hypotheses_, camera, types, planner_.parameters(), &map_);
}

void NbvViewPlanner::removeObjects(const std::vector<ObjectKey>& objects) {
  hypotheses_.removeObjects(objects);
}

}  // namespace asr_state_machine
