#pragma once

#include <actionlib/client/simple_action_client.h>
#include <asr_msgs/MoveRobotAction.h>
#include <asr_msgs/RobotState.h>
#include <ros/ros.h>

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "asr_robot_model/robot_description.hpp"
#include "asr_state_machine/parts.hpp"
#include "asr_state_machine/ros/timed_service_call.hpp"

// The parts of the search as clients of the suite's nodes (docs/search.md): the robot over
// robot_driver's move_robot action and robot_state topic, the detector over detect_objects
// (object_detector_sim or apriltag_detector), recognition over scene_recognizer's
// recognize_scenes, prediction over pose_predictor's predict_poses, the next best view over
// next_best_view's services. A node that does not answer within its timeout, whose service is
// gone or whose call fails three times throws PartFailure naming it: the search ends `aborted`
// with the reason.
namespace asr_state_machine::ros_interface {

/// The robot behind robot_driver. The motion's timeout counts from the driver's last sign of
/// progress (feedback), so long motions on a slow clock are fine while a stalled driver is not.
class RosRobot : public Robot {
 public:
  /// Waits up to `startup_timeout` wall seconds for the driver's action server and robot state.
  RosRobot(ros::NodeHandle& node, const asr_robot_model::RobotDescription& robot, PartEndpoint part,
           double startup_timeout);
  RobotState state() override;
  MoveResult moveTo(const RobotState& goal) override;

 private:
  void onState(const asr_msgs::RobotState& message);

  const asr_robot_model::RobotDescription& robot_;
  PartEndpoint part_;
  actionlib::SimpleActionClient<asr_msgs::MoveRobotAction> client_;
  ros::Subscriber state_subscriber_;
  std::mutex mutex_;
  std::optional<RobotState> state_;
  ros::WallTime last_progress_;
};

/// Detection over a detect_objects service; estimates arrive in the map frame. Invalid
/// estimates (NaN, zero quaternion, another frame) are skipped with a warning.
class RosDetector : public Detector {
 public:
  RosDetector(std::string frame, PartEndpoint part);
  DetectionResult detect(const Pose& camera, const std::vector<std::string>& types) override;

 private:
  std::string frame_;
  PartEndpoint part_;
};

/// Recognition over recognize_scenes. Which objects each scene has comes from the models the
/// executive loaded (the same files the recogniser loads).
class RosRecognizer : public Recognizer {
 public:
  RosRecognizer(std::map<std::string, std::vector<ObjectKey>> scene_objects,
                std::vector<std::string> scenes, std::string frame, PartEndpoint part);
  std::map<std::string, std::vector<ObjectKey>> sceneObjects() override { return scene_objects_; }
  std::vector<SceneInstance> recognize(const asr_common::Configuration& found) override;

 private:
  std::map<std::string, std::vector<ObjectKey>> scene_objects_;
  std::vector<std::string> scenes_;
  std::string frame_;
  PartEndpoint part_;
};

/// Prediction over predict_poses; the clouds of one object over all instances are merged.
class RosPredictor : public Predictor {
 public:
  /// `samples` poses per missing object and instance, from the best `instances` per scene.
  RosPredictor(std::size_t samples, std::size_t instances, std::string frame, PartEndpoint part);
  std::vector<PredictedCloud> predict(const std::vector<SceneInstance>& instances,
                                      const std::vector<ObjectKey>& missing,
                                      std::uint32_t seed) override;

 private:
  std::size_t samples_;
  std::size_t instances_;
  std::string frame_;
  PartEndpoint part_;
};

/// The next best view over next_best_view's services; a request the node refuses (its
/// `message`) is a PartFailure.
class RosViewPlanner : public ViewPlanner {
 public:
  RosViewPlanner(std::string frame, PartEndpoint part);
  std::size_t setHypotheses(const std::vector<PredictedCloud>& clouds,
                            const std::vector<VisitedView>& visited) override;
  PlannedView next(const RobotState& current) override;
  std::size_t update(const Pose& camera, const std::vector<std::string>& types) override;
  void removeObjects(const std::vector<ObjectKey>& objects) override;

 private:
  std::string frame_;
  PartEndpoint part_;
};

/// Waits up to `timeout` wall seconds for each of `services`; throws PartFailure naming the
/// node and the first service missing.
void waitForServices(const PartEndpoint& part, const std::vector<std::string>& services,
                     double timeout);

}  // namespace asr_state_machine::ros_interface
