#pragma once

#include <asr_msgs/ObjectEstimateList.h>
#include <asr_msgs/RecognizeScenes.h>
#include <asr_msgs/ReloadModel.h>
#include <asr_msgs/SceneInstanceList.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "asr_ism/latest_estimates.hpp"
#include "asr_ism/ros/estimate_intake.hpp"
#include "asr_ism_tree/continuous_recognition.hpp"
#include "asr_ism_tree/scene_models.hpp"

namespace asr_ism_tree::ros_interface {

/// The scene recogniser node. Parameters (private): model_files (list, required), scenes (list;
/// empty: all), fixed_frame (map), continuous (true), rate (Hz, 10), estimate_timeout (s, 5; 0:
/// never), max_estimates (1000: larger requests are refused with a message), threads (0: one per
/// core; scenes are recognised in parallel) and the searches' work limits. Services
/// recognize_scenes and reload_model; in continuous mode the latest estimate of every object from
/// topic `objects` is recognised at `rate` and published on scene_instances and scene_markers.
/// Rejected estimates are counted on ~rejected_estimates (latched). Recognition runs outside the
/// lock on a snapshot of the models, so a service call (on its own thread) never holds up the
/// timer. In continuous mode each scene is recognised on a thread of its own, anew only where
/// the estimates of its objects' types changed (ContinuousRecognition), and every tick publishes
/// each scene's latest instances, each stamped with the time of the estimates it came from: the
/// output keeps `rate`, a scene seen well follows within a period or two, and a badly seen one
/// lags by what its searches take.
class SceneRecognizerNode {
 public:
  /// Reads and checks the parameters and loads the models: throws InputError naming the
  /// parameter or file.
  explicit SceneRecognizerNode(ros::NodeHandle node, ros::NodeHandle private_node);

 private:
  void readWorkLimits();
  bool recognize(asr_msgs::RecognizeScenes::Request& request,
                 asr_msgs::RecognizeScenes::Response& response);
  bool reload(asr_msgs::ReloadModel::Request& request, asr_msgs::ReloadModel::Response& response);
  // The topic and timer callbacks guard what they call (callback_guard.hpp).
  void receive(const asr_msgs::ObjectEstimateList& message);
  void store(const asr_msgs::ObjectEstimateList& message);
  void tick(const ros::TimerEvent& event);
  void publishLatest(const SceneModels& models, const std::string& frame);
  void publishRejected();

  ros::NodeHandle node_;
  ros::NodeHandle private_node_;
  std::vector<std::string> model_files_;
  std::vector<std::string> scenes_;
  double estimate_timeout_ = 5.0;

  tf2_ros::Buffer buffer_;
  tf2_ros::TransformListener listener_;
  std::mutex mutex_;  // models_ (the pointer), intake_, latest_
  // Replaced whole by a reload; a recognition in progress keeps the models it started with.
  std::shared_ptr<const SceneModels> models_;
  TreeRecognitionParameters recognition_parameters_;
  asr_ism::ros_interface::EstimateIntake intake_;
  asr_ism::LatestEstimates latest_;
  ros::Time newest_stamp_;
  unsigned threads_ = 0;  // of the models' pool

  ros::Publisher instances_publisher_;
  ros::Publisher markers_publisher_;
  ros::Publisher rejected_publisher_;
  ros::Subscriber subscriber_;
  ros::ServiceServer recognize_service_;
  ros::ServiceServer reload_service_;
  ros::Timer timer_;
  // In continuous mode; offered and read by the timer only. Last: destroyed first, so a running
  // recognition ends while what it uses still exists.
  std::unique_ptr<ContinuousRecognition> continuous_;
};

}  // namespace asr_ism_tree::ros_interface
