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
#include "asr_ism/periodic_output.hpp"
#include "asr_ism/ros/estimate_intake.hpp"
#include "asr_ism_tree/incremental_recognition.hpp"
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
/// timer. The continuous recognitions run on a thread of their own (PeriodicOutput) and
/// recognise anew only the scenes whose estimates changed; a list is published as soon as it is
/// recognised, and a tick that finds the last recognition still running publishes the last list
/// again (stamped with its estimates' time), so the output keeps `rate` while its content lags
/// (by up to two recognitions).
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
  struct RecognizedList {
    asr_msgs::SceneInstanceList list;
    std::optional<visualization_msgs::MarkerArray> markers;  // where someone listens
  };
  std::optional<RecognizedList> recognizeLatest(const asr_common::Configuration& configuration,
                                                const std::shared_ptr<const SceneModels>& models,
                                                const std_msgs::Header& header);
  void publish(const RecognizedList& recognized, bool fresh);
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
  // The continuous recognitions (only the output's worker thread touches it): one recognises
  // anew only the scenes whose estimates changed and returns the others' last instances again.
  IncrementalRecognition continuous_;

  ros::Publisher instances_publisher_;
  ros::Publisher markers_publisher_;
  ros::Publisher rejected_publisher_;
  ros::Subscriber subscriber_;
  ros::ServiceServer recognize_service_;
  ros::ServiceServer reload_service_;
  ros::Timer timer_;
  // Last: destroyed first, so a running recognition ends while what it uses still exists.
  asr_ism::PeriodicOutput<RecognizedList> output_;
};

}  // namespace asr_ism_tree::ros_interface
