#include "asr_pose_prediction/ros/pose_predictor_node.hpp"

#include <visualization_msgs/MarkerArray.h>

#include "asr_common/input_error.hpp"
#include "asr_common/ros/callback_guard.hpp"
#include "asr_common/ros/node_parameters.hpp"
#include "asr_common/ros/queue_sizes.hpp"
#include "asr_ism_tree/ros/scene_instance_message.hpp"
#include "asr_pose_prediction/ros/pose_cloud_message.hpp"
#include "asr_pose_prediction/ros/prediction_markers.hpp"

namespace asr_pose_prediction::ros_interface {

using namespace asr_common::ros_interface;

PosePredictorNode::PosePredictorNode(ros::NodeHandle node, ros::NodeHandle private_node)
    : node_(node) {
  const std::vector<std::string> files = stringListParameter(private_node, "model_files");
  checkParameter(private_node, "model_files", !files.empty(),
                 "set to the model files to load (a list, or one file)");
  const long long samples = integerParameter(private_node, "samples", 100, 1, kMaxSamples);
  const long long best = integerParameter(private_node, "best_instances", 1, 1, kMaxInstances);
  const long long seed = integerParameter(private_node, "seed", 0, 0, 4294967295LL);
  const bool continuous = optionalParameter<bool>(private_node, "continuous", true);
  defaults_.samples = static_cast<std::size_t>(samples);
  defaults_.instances = static_cast<std::size_t>(best);
  defaults_.seed = static_cast<std::uint32_t>(seed);

  models_ = asr_ism_tree::SceneModels::load(files);
  for (const std::string& scene : models_.scenes())
    predictors_.emplace(scene, PosePredictor(models_.tree(scene)));

  clouds_publisher_ =
      node_.advertise<asr_msgs::PredictedPoseCloud>("predicted_poses", kResultQueue);
  markers_publisher_ =
      node_.advertise<visualization_msgs::MarkerArray>("prediction_markers", kLatchedQueue, true);
  subscriber_ = node_.subscribe("scene_instances", kResultQueue, &PosePredictorNode::receive, this);
  service_ = node_.advertiseService("predict_poses", &PosePredictorNode::predictService, this);
  continuous_ = continuous;
  ROS_INFO("pose_predictor: %zu scenes, %lld poses per missing object", predictors_.size(),
           samples);
}

std::vector<asr_msgs::PredictedPoseCloud> PosePredictorNode::predict(
    const std::vector<SceneInstance>& instances, const PredictionOptions& options,
    const std_msgs::Header& header, std::string& message) const {
  // Instances grouped by scene, each group in the order given (best first).
  std::map<std::string, std::vector<SceneInstance>> by_scene;
  std::vector<std::string> order;
  for (const SceneInstance& instance : instances) {
    if (!by_scene.count(instance.scene))
      order.push_back(instance.scene);
    by_scene[instance.scene].push_back(instance);
  }
  std::vector<asr_msgs::PredictedPoseCloud> clouds;
  for (const std::string& scene : order) {
    const auto predictor = predictors_.find(scene);
    if (predictor == predictors_.end()) {
      message += (message.empty() ? "" : "; ") + std::string("no model of scene '") + scene + "'";
      continue;
    }
    std::vector<SceneInstance>& group = by_scene[scene];
    group.resize(std::min(group.size(), options.instances));
    const std::vector<ObjectPrediction> predictions = predictor->second.predict(group, options);
    for (auto& cloud : toPoseCloudMessages(predictions, group, header))
      clouds.push_back(std::move(cloud));
  }
  if (clouds.empty() && message.empty())
    message = instances.empty() ? "no scene instance to predict from"
                                : "every instance is complete: nothing to predict";
  return clouds;
}

bool PosePredictorNode::predictService(asr_msgs::PredictPoses::Request& request,
                                       asr_msgs::PredictPoses::Response& response) {
  PredictionOptions options = defaults_;
  if (request.samples > 0)
    options.samples = request.samples;
  if (request.best_instances > 0)
    options.instances = request.best_instances;
  options.seed = request.seed;
  std_msgs::Header header;
  std::vector<SceneInstance> instances;
  try {
    const std::vector<asr_msgs::SceneInstance>* source = &request.instances;
    asr_msgs::SceneInstanceList latest;
    if (request.instances.empty()) {
      std::lock_guard<std::mutex> lock(mutex_);
      latest = latest_;
      source = &latest.instances;
      header = latest.header;
    } else {
      header = request.instances.front().header;
    }
    for (const asr_msgs::SceneInstance& instance : *source)
      instances.push_back(asr_ism_tree::ros_interface::fromSceneInstanceMessage(instance));
    response.clouds = predict(instances, options, header, response.message);
  } catch (const asr_common::InputError& error) {
    response.clouds.clear();
    response.message = error.what();
  }
  if (!response.clouds.empty())
    publish(response.clouds);
  return true;
}

void PosePredictorNode::receive(const asr_msgs::SceneInstanceList& list) {
  asr_common::ros_interface::guardCallback("pose_predictor: scene_instances",
                                           [&] { predictLatest(list); });
}

void PosePredictorNode::predictLatest(const asr_msgs::SceneInstanceList& list) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    latest_ = list;
  }
  if (!continuous_)
    return;
  try {
    std::vector<SceneInstance> instances;
    for (const asr_msgs::SceneInstance& instance : list.instances)
      instances.push_back(asr_ism_tree::ros_interface::fromSceneInstanceMessage(instance));
    std::string message;
    publish(predict(instances, defaults_, list.header, message));
  } catch (const asr_common::InputError& error) {
    ROS_WARN_THROTTLE(5.0, "pose_predictor: %s", error.what());
  }
}

void PosePredictorNode::publish(const std::vector<asr_msgs::PredictedPoseCloud>& clouds) {
  for (const asr_msgs::PredictedPoseCloud& cloud : clouds)
    clouds_publisher_.publish(cloud);
  if (markers_publisher_.getNumSubscribers() > 0)
    markers_publisher_.publish(predictionMarkers(clouds, {}));
}

}  // namespace asr_pose_prediction::ros_interface
