#include "asr_state_machine/ros/ros_parts.hpp"

#include <asr_msgs/DetectObjects.h>
#include <asr_msgs/GetNextBestView.h>
#include <asr_msgs/PredictPoses.h>
#include <asr_msgs/RecognizeScenes.h>
#include <asr_msgs/RemoveNbvObjects.h>
#include <asr_msgs/SetNbvHypotheses.h>
#include <asr_msgs/UpdateNbvHypotheses.h>

#include <algorithm>

#include "asr_common/input_error.hpp"
#include "asr_common/ros/object_estimate_message.hpp"
#include "asr_ism_tree/ros/scene_instance_message.hpp"
#include "asr_robot_model/forward_kinematics.hpp"
#include "asr_robot_model/ros/robot_state_message.hpp"

namespace asr_state_machine::ros_interface {

namespace {

using asr_common::ros_interface::fromEstimateMessage;
using asr_common::ros_interface::fromPoseMessage;
using asr_common::ros_interface::toEstimateMessage;
using asr_common::ros_interface::toPoseMessage;
using asr_robot_model::ros_interface::fromStateMessage;
using asr_robot_model::ros_interface::toStateMessage;

std_msgs::Header headerIn(const std::string& frame) {
  std_msgs::Header header;
  header.frame_id = frame;
  header.stamp = ros::Time::now();
  return header;
}

void throwIfRefused(const PartEndpoint& part, const std::string& service,
                    const std::string& message) {
  if (!message.empty())
    throw PartFailure(part.node, service + " refused: " + message);
}

}  // namespace

void waitForServices(const PartEndpoint& part, const std::vector<std::string>& services,
                     double timeout) {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout);
  for (const std::string& service : services) {
    const std::string resolved = ros::NodeHandle().resolveName(service);
    while (!ros::service::exists(resolved, false)) {
      if (!ros::ok() || ros::WallTime::now() > deadline) {
        throw PartFailure(part.node, "service " + resolved + " did not appear within " +
                                         std::to_string(static_cast<int>(timeout)) + " s");
      }
      ros::WallDuration(0.1).sleep();
    }
  }
}

RosRobot::RosRobot(ros::NodeHandle& node, const asr_robot_model::RobotDescription& robot,
                   PartEndpoint part, double startup_timeout)
    : robot_(robot), part_(std::move(part)), client_(node, "move_robot", true) {
  state_subscriber_ = node.subscribe("robot_state", 1, &RosRobot::onState, this);
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(startup_timeout);
  while (!client_.isServerConnected() || !state_) {
    if (!ros::ok() || ros::WallTime::now() > deadline) {
      throw PartFailure(part_.node, client_.isServerConnected()
                                        ? "no robot_state within the timeout"
                                        : "action move_robot did not appear within the timeout");
    }
    ros::WallDuration(0.05).sleep();
  }
}

void RosRobot::onState(const asr_msgs::RobotState& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  state_ = fromStateMessage(message);
  last_progress_ = ros::WallTime::now();
}

RobotState RosRobot::state() {
  std::lock_guard<std::mutex> lock(mutex_);
  return *state_;
}

MoveResult RosRobot::moveTo(const RobotState& goal) {
  asr_msgs::MoveRobotGoal message;
  message.target = toStateMessage(goal);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    last_progress_ = ros::WallTime::now();
  }
  client_.sendGoal(message, {}, {}, [this](const asr_msgs::MoveRobotFeedbackConstPtr&) {
    std::lock_guard<std::mutex> lock(mutex_);
    last_progress_ = ros::WallTime::now();
  });
  while (!client_.getState().isDone()) {
    if (!ros::ok())
      throw PartFailure(part_.node, "shut down while moving");
    bool stalled = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stalled = ros::WallTime::now() - last_progress_ > ros::WallDuration(part_.timeout);
    }
    if (stalled || !client_.isServerConnected()) {
      client_.cancelGoal();
      throw PartFailure(part_.node, stalled ? "move_robot made no progress for " +
                                                  std::to_string(static_cast<int>(part_.timeout)) +
                                                  " s (wall clock)"
                                            : "action move_robot is gone (node down?)");
    }
    ros::WallDuration(0.005).sleep();
  }
  const auto result = client_.getResult();
  if (client_.getState() != actionlib::SimpleClientGoalState::SUCCEEDED || !result ||
      result->outcome != asr_msgs::MoveRobotResult::REACHED) {
    throw PartFailure(part_.node, "move_robot failed: " + (result && !result->message.empty()
                                                               ? result->message
                                                               : client_.getState().toString()));
  }
  MoveResult moved;
  moved.reached = fromStateMessage(result->state);
  {
    // The robot_state topic may still be on its way: the action's result is the newer word.
    std::lock_guard<std::mutex> lock(mutex_);
    state_ = moved.reached;
  }
  moved.camera = asr_robot_model::cameraPose(robot_, moved.reached);
  moved.seconds = result->seconds;
  return moved;
}

RosDetector::RosDetector(std::string frame, PartEndpoint part)
    : frame_(std::move(frame)), part_(std::move(part)) {}

DetectionResult RosDetector::detect(const Pose&, const std::vector<std::string>& types) {
  asr_msgs::DetectObjects service;
  service.request.types = types;
  callService(part_, "detect_objects", service);
  DetectionResult result;
  result.seconds = service.response.seconds;
  for (const asr_msgs::ObjectEstimate& message : service.response.estimates.objects) {
    if (message.header.frame_id != frame_) {
      ROS_WARN("search_executive: %s skipped: not in %s",
               asr_common::ros_interface::describe(message).c_str(), frame_.c_str());
      continue;
    }
    try {
      result.estimates.push_back(fromEstimateMessage(message));
    } catch (const asr_common::InputError& error) {
      ROS_WARN("search_executive: detection skipped: %s", error.what());
    }
  }
  return result;
}

RosRecognizer::RosRecognizer(std::map<std::string, std::vector<ObjectKey>> scene_objects,
                             std::vector<std::string> scenes, std::string frame, PartEndpoint part)
    : scene_objects_(std::move(scene_objects)),
      scenes_(std::move(scenes)),
      frame_(std::move(frame)),
      part_(std::move(part)) {}

std::vector<SceneInstance> RosRecognizer::recognize(const asr_common::Configuration& found) {
  asr_msgs::RecognizeScenes service;
  const std_msgs::Header header = headerIn(frame_);
  for (const ObjectEstimate& estimate : found)
    service.request.objects.push_back(toEstimateMessage(estimate, header));
  service.request.scenes = scenes_;
  callService(part_, "recognize_scenes", service);
  if (service.response.rejected_estimates > 0) {
    throw PartFailure(part_.node, "recognize_scenes rejected " +
                                      std::to_string(service.response.rejected_estimates) +
                                      " of the found objects: " + service.response.message);
  }
  std::vector<SceneInstance> instances;
  try {
    for (const asr_msgs::SceneInstance& message : service.response.instances)
      instances.push_back(asr_ism_tree::ros_interface::fromSceneInstanceMessage(message));
  } catch (const asr_common::InputError& error) {
    throw PartFailure(part_.node, std::string("an instance is malformed: ") + error.what());
  }
  return instances;
}

RosPredictor::RosPredictor(std::size_t samples, std::size_t instances, std::string frame,
                           PartEndpoint part)
    : samples_(samples), instances_(instances), frame_(std::move(frame)), part_(std::move(part)) {}

std::vector<PredictedCloud> RosPredictor::predict(const std::vector<SceneInstance>& instances,
                                                  const std::vector<ObjectKey>& missing,
                                                  std::uint32_t seed) {
  // An empty request would ask for the recogniser's latest instances instead.
  if (instances.empty())
    return {};
  asr_msgs::PredictPoses service;
  const std_msgs::Header header = headerIn(frame_);
  for (const SceneInstance& instance : instances) {
    service.request.instances.push_back(
        asr_ism_tree::ros_interface::toSceneInstanceMessage(instance, header));
  }
  service.request.samples = static_cast<std::uint32_t>(samples_);
  service.request.best_instances = static_cast<std::uint32_t>(instances_);
  service.request.seed = seed;
  callService(part_, "predict_poses", service);
  std::map<ObjectKey, PredictedCloud> clouds;
  for (const asr_msgs::PredictedPoseCloud& cloud : service.response.clouds) {
    if (cloud.header.frame_id != frame_) {
      throw PartFailure(
          part_.node, "predicted poses in frame '" + cloud.header.frame_id + "', not in " + frame_);
    }
    for (const asr_msgs::PredictedObjectPoses& object : cloud.objects) {
      const ObjectKey key{object.type, object.instance_id};
      if (std::find(missing.begin(), missing.end(), key) == missing.end())
        continue;
      PredictedCloud& merged = clouds[key];
      merged.key = key;
      for (const geometry_msgs::Pose& pose : object.poses) {
        try {
          merged.poses.push_back(fromPoseMessage(pose, "a predicted pose of " + key.toString()));
        } catch (const asr_common::InputError& error) {
          ROS_WARN_THROTTLE(5.0, "search_executive: %s", error.what());
        }
      }
    }
  }
  std::vector<PredictedCloud> result;
  for (auto& [key, cloud] : clouds)
    result.push_back(std::move(cloud));
  return result;
}

RosViewPlanner::RosViewPlanner(std::string frame, PartEndpoint part)
    : frame_(std::move(frame)), part_(std::move(part)) {}

std::size_t RosViewPlanner::setHypotheses(const std::vector<PredictedCloud>& clouds,
                                          const std::vector<VisitedView>& visited) {
  asr_msgs::SetNbvHypotheses service;
  for (const PredictedCloud& cloud : clouds) {
    asr_msgs::PredictedPoseCloud message;
    message.header = headerIn(frame_);
    asr_msgs::PredictedObjectPoses object;
    object.type = cloud.key.type;
    object.instance_id = cloud.key.id;
    for (const Pose& pose : cloud.poses)
      object.poses.push_back(toPoseMessage(pose));
    message.objects.push_back(std::move(object));
    service.request.clouds.push_back(std::move(message));
  }
  for (const VisitedView& view : visited) {
    asr_msgs::VisitedView message;
    message.camera = toPoseMessage(view.camera);
    message.types = view.types;
    service.request.visited.push_back(std::move(message));
  }
  callService(part_, "set_nbv_hypotheses", service);
  throwIfRefused(part_, "set_nbv_hypotheses", service.response.message);
  return service.response.counting;
}

PlannedView RosViewPlanner::next(const RobotState& current) {
  asr_msgs::GetNextBestView service;
  service.request.current = toStateMessage(current);
  callService(part_, "get_next_best_view", service);
  const asr_msgs::GetNextBestView::Response& response = service.response;
  throwIfRefused(part_, "get_next_best_view", response.message);
  PlannedView planned;
  planned.found = response.found;
  if (planned.found) {
    try {
      planned.camera = fromPoseMessage(response.view.camera, "the next best view's camera");
    } catch (const asr_common::InputError& error) {
      throw PartFailure(part_.node, error.what());
    }
    planned.state = fromStateMessage(response.view.state);
    planned.types = response.view.types;
  }
  planned.utility = response.utility;
  planned.utility_max = response.utility_max;
  planned.rating = response.rating;
  planned.costs = {response.costs.base, response.costs.rotation, response.costs.pan_tilt,
                   response.costs.recognition};
  planned.motion_seconds = response.costs.motion_seconds;
  planned.candidates_rated = response.candidates_rated;
  planned.steps = response.steps;
  return planned;
}

std::size_t RosViewPlanner::update(const Pose& camera, const std::vector<std::string>& types) {
  asr_msgs::UpdateNbvHypotheses service;
  service.request.camera = toPoseMessage(camera);
  service.request.types = types;
  callService(part_, "update_nbv_hypotheses", service);
  throwIfRefused(part_, "update_nbv_hypotheses", service.response.message);
  return service.response.deactivated_normals;
}

void RosViewPlanner::removeObjects(const std::vector<ObjectKey>& objects) {
  asr_msgs::RemoveNbvObjects service;
  for (const ObjectKey& key : objects) {
    asr_msgs::ObjectKey message;
    message.type = key.type;
    message.instance_id = key.id;
    service.request.objects.push_back(message);
  }
  callService(part_, "remove_nbv_objects", service);
  throwIfRefused(part_, "remove_nbv_objects", service.response.message);
}

}  // namespace asr_state_machine::ros_interface
