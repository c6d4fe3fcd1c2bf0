#pragma once

#include <asr_msgs/PredictPoses.h>
#include <asr_msgs/SceneInstanceList.h>
#include <ros/ros.h>

#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "asr_ism_tree/scene_models.hpp"
#include "asr_pose_prediction/pose_predictor.hpp"

namespace asr_pose_prediction::ros_interface {

/// The pose predictor node. Parameters (private): model_files (list or one file, required),
/// samples (100 poses per missing object), best_instances (1), seed (0), continuous (true).
/// Service predict_poses: predicts for the instances of the request, or for the latest ones
/// received on scene_instances; in continuous mode every scene_instances message with an
/// incomplete instance is answered on predicted_poses (one cloud per instance) and
/// prediction_markers.
class PosePredictorNode {
 public:
  /// Reads and checks the parameters, loads the models and prepares a predictor per scene:
  /// throws InputError naming the parameter or file.
  PosePredictorNode(ros::NodeHandle node, ros::NodeHandle private_node);

 private:
  bool predictService(asr_msgs::PredictPoses::Request& request,
                      asr_msgs::PredictPoses::Response& response);
  // The topic callback guards what it calls (callback_guard.hpp).
  void receive(const asr_msgs::SceneInstanceList& list);
  void predictLatest(const asr_msgs::SceneInstanceList& list);
  /// Clouds for `instances` (any scenes; best first within a scene); `message` says why there
  /// are none.
  std::vector<asr_msgs::PredictedPoseCloud> predict(const std::vector<SceneInstance>& instances,
                                                    const PredictionOptions& options,
                                                    const std_msgs::Header& header,
                                                    std::string& message) const;
  void publish(const std::vector<asr_msgs::PredictedPoseCloud>& clouds);

  ros::NodeHandle node_;
  asr_ism_tree::SceneModels models_;
  std::map<std::string, PosePredictor> predictors_;
  PredictionOptions defaults_;
  bool continuous_ = true;
  std::mutex mutex_;  // latest_
  asr_msgs::SceneInstanceList latest_;
  ros::Publisher clouds_publisher_;
  ros::Publisher markers_publisher_;
  ros::Subscriber subscriber_;
  ros::ServiceServer service_;
};

}  // namespace asr_pose_prediction::ros_interface
