#include "asr_ism_tree/ros/scene_recognizer_node.hpp"

#include <asr_msgs/SceneInstanceList.h>
#include <std_msgs/UInt32.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <map>
#include <string>

#include "asr_common/input_error.hpp"
#include "asr_common/ros/callback_guard.hpp"
#include "asr_common/ros/node_parameters.hpp"
#include "asr_common/ros/queue_sizes.hpp"
#include "asr_ism_tree/ros/scene_instance_message.hpp"
#include "asr_ism_tree/ros/scene_markers.hpp"

namespace asr_ism_tree::ros_interface {

using namespace asr_common::ros_interface;

SceneRecognizerNode::SceneRecognizerNode(ros::NodeHandle node, ros::NodeHandle private_node)
    : node_(node),
      private_node_(private_node),
      listener_(buffer_),
      intake_(buffer_, fixedFrameParameter(private_node)) {
  model_files_ = stringListParameter(private_node_, "model_files");
  checkParameter(private_node_, "model_files", !model_files_.empty(),
                 "set to the model files to load (a list, or one file)");
  scenes_ = stringListParameter(private_node_, "scenes");
  const bool continuous = optionalParameter<bool>(private_node_, "continuous", true);
  const double rate = numberParameter(private_node_, "rate", 10.0, 0.001, 1000.0);
  // 0: estimates never expire.
  estimate_timeout_ = numberParameter(private_node_, "estimate_timeout", 5.0, 0.0, 1e9);
  // Requests with more estimates are refused with a message.
  recognition_parameters_.max_estimates =
      static_cast<std::size_t>(integerParameter(private_node_, "max_estimates", 1000, 1, 1000000));
  readWorkLimits();
  threads_ = static_cast<unsigned>(integerParameter(private_node_, "threads", 0, 0, 1024));
  models_ = std::make_shared<const SceneModels>(
      SceneModels::load(model_files_, scenes_, recognition_parameters_, threads_));

  instances_publisher_ =
      node_.advertise<asr_msgs::SceneInstanceList>("scene_instances", kResultQueue);
  markers_publisher_ =
      node_.advertise<visualization_msgs::MarkerArray>("scene_markers", kLatchedQueue, true);
  rejected_publisher_ =
      private_node_.advertise<std_msgs::UInt32>("rejected_estimates", kLatchedQueue, true);
  publishRejected();
  recognize_service_ =
      node_.advertiseService("recognize_scenes", &SceneRecognizerNode::recognize, this);
  reload_service_ = node_.advertiseService("reload_model", &SceneRecognizerNode::reload, this);
  if (continuous) {
    // Slow scenes share one slot per thread of the models' pool; a scene recognised within its
    // share of a period is quick and follows its estimates every tick.
    continuous_ = std::make_unique<ContinuousRecognition>(
        [](std::exception_ptr error) {
          // On a scene's thread: input errors were refused at the offer, so this is unexpected.
          try {
            std::rethrow_exception(error);
          } catch (const std::exception& e) {
            ROS_ERROR_THROTTLE(5.0, "scene_recognizer: continuous recognition failed: %s",
                               e.what());
          } catch (...) {
            ROS_ERROR_THROTTLE(5.0, "scene_recognizer: continuous recognition failed");
          }
        },
        ContinuousPace{threads_, 1.0 / rate});
    subscriber_ = node_.subscribe("objects", kEstimateQueue, &SceneRecognizerNode::receive, this);
    timer_ = node_.createTimer(ros::Duration(1.0 / rate), &SceneRecognizerNode::tick, this);
  }
  std::string loaded;
  for (const std::string& scene : models_->scenes())
    loaded += (loaded.empty() ? "" : ", ") + scene;
  ROS_INFO("scene_recognizer: %zu scenes loaded (%s), %s", models_->scenes().size(), loaded.c_str(),
           continuous ? "continuous mode" : "service only");
}

// The library's work limits of the searches that make the best exact (TreeRecognitionParameters;
// its defaults where not set). Lower ones shorten a recognition where scenes are seen badly or
// not at all (a tick of ten kitchen scenes: 2 s with the defaults), at the price of bests that
// are more often lower bounds (search_complete false); 0 gives each search up at once.
void SceneRecognizerNode::readWorkLimits() {
  constexpr long long kMaxWork = 1000000000000LL;
  const auto read = [&](const char* name, std::size_t& limit) {
    limit = static_cast<std::size_t>(
        integerParameter(private_node_, name, static_cast<long long>(limit), 0, kMaxWork));
  };
  read("exact_search_max_comparisons", recognition_parameters_.exact_search_max_comparisons);
  read("diverse_max_comparisons", recognition_parameters_.diverse_max_comparisons);
  read("object_subsets_max_work", recognition_parameters_.object_subsets_max_work);
}

bool SceneRecognizerNode::recognize(asr_msgs::RecognizeScenes::Request& request,
                                    asr_msgs::RecognizeScenes::Response& response) {
  asr_common::Configuration configuration;
  std::shared_ptr<const SceneModels> models;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    models = models_;
    const std::size_t rejected_before = intake_.rejectedCount();
    for (const asr_msgs::ObjectEstimate& estimate : request.objects) {
      if (auto accepted = intake_.accept(estimate))
        configuration.push_back(*accepted);
    }
    response.rejected_estimates =
        static_cast<std::uint32_t>(intake_.rejectedCount() - rejected_before);
    if (response.rejected_estimates > 0)
      publishRejected();
  }
  try {
    const std::vector<SceneInstance> instances = models->recognize(configuration, request.scenes);
    std_msgs::Header header;
    header.stamp = ros::Time::now();
    header.frame_id = intake_.fixedFrame();
    for (const SceneInstance& instance : instances)
      response.instances.push_back(toSceneInstanceMessage(instance, header));
    if (instances.empty())
      response.message = configuration.empty() ? "no valid object estimate in the request"
                                               : "no instance of the scenes asked for";
  } catch (const asr_common::InputError& error) {
    response.message = error.what();
  }
  return true;
}

bool SceneRecognizerNode::reload(asr_msgs::ReloadModel::Request& request,
                                 asr_msgs::ReloadModel::Response& response) {
  const std::vector<std::string> files =
      request.model_files.empty() ? model_files_ : request.model_files;
  try {
    auto loaded = std::make_shared<const SceneModels>(
        SceneModels::load(files, scenes_, recognition_parameters_, threads_));
    std::lock_guard<std::mutex> lock(mutex_);
    models_ = std::move(loaded);
    model_files_ = files;
    response.success = true;
  } catch (const asr_common::InputError& error) {
    response.success = false;
    response.message = std::string(error.what()) + "; the previous models stay in use";
    ROS_WARN("scene_recognizer: reload failed: %s", response.message.c_str());
  }
  std::lock_guard<std::mutex> lock(mutex_);
  response.scenes = models_->scenes();
  return true;
}

void SceneRecognizerNode::receive(const asr_msgs::ObjectEstimateList& message) {
  asr_common::ros_interface::guardCallback("scene_recognizer: objects", [&] { store(message); });
}

void SceneRecognizerNode::store(const asr_msgs::ObjectEstimateList& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  const std::size_t rejected_before = intake_.rejectedCount();
  for (const asr_msgs::ObjectEstimate& estimate : message.objects) {
    if (auto accepted = intake_.accept(estimate)) {
      latest_.update(*accepted, estimate.header.stamp.toSec());
      newest_stamp_ = std::max(newest_stamp_, estimate.header.stamp);
    }
  }
  if (intake_.rejectedCount() != rejected_before)
    publishRejected();
}

// The timer never waits for a recognition: each scene runs on its own thread, and a tick
// publishes what each has recognised so far. A refused configuration (the guard reports it)
// drops every result, so nothing is published until one is accepted.
void SceneRecognizerNode::tick(const ros::TimerEvent&) {
  asr_common::ros_interface::guardCallback("scene_recognizer: continuous recognition", [&] {
    auto configuration = std::make_shared<asr_common::Configuration>();
    std::shared_ptr<const SceneModels> models;
    ros::Time stamp;
    std::string frame;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      *configuration = latest_.current(ros::Time::now().toSec(), estimate_timeout_);
      models = models_;
      stamp = newest_stamp_;
      frame = intake_.fixedFrame();
    }
    continuous_->offer(models, configuration, stamp.toNSec());
    publishLatest(*models, frame);
  });
}

// Every scene's latest instances, best first, each stamped with the time of the estimates it was
// recognised from; the list with the newest of those. The markers (latched) go out where some
// scene's result is new.
void SceneRecognizerNode::publishLatest(const SceneModels& models, const std::string& frame) {
  const ContinuousRecognition::Latest latest = continuous_->latest();
  asr_msgs::SceneInstanceList list;
  list.header.frame_id = frame;
  std::vector<SceneInstance> instances;
  std::map<std::string, ros::Time> stamp_of_scene;
  bool recognized = false;
  for (const auto& result : latest.scenes) {
    if (!result)
      continue;
    recognized = true;
    ros::Time stamp;
    stamp.fromNSec(result->stamp);
    list.header.stamp = std::max(list.header.stamp, stamp);
    for (const SceneInstance& instance : result->instances) {
      instances.push_back(instance);
      stamp_of_scene[instance.scene] = stamp;
    }
  }
  if (!recognized)
    return;  // nothing recognised yet since the models were loaded or a refusal
  sortByConfidence(instances);
  std_msgs::Header header = list.header;
  for (const SceneInstance& instance : instances) {
    header.stamp = stamp_of_scene[instance.scene];
    list.instances.push_back(toSceneInstanceMessage(instance, header));
  }
  instances_publisher_.publish(list);
  if (latest.fresh > 0 && markers_publisher_.getNumSubscribers() > 0)
    markers_publisher_.publish(sceneInstanceMarkers(instances, models, list.header));
}

void SceneRecognizerNode::publishRejected() {
  std_msgs::UInt32 count;
  count.data = static_cast<std::uint32_t>(intake_.rejectedCount());
  rejected_publisher_.publish(count);
}

}  // namespace asr_ism_tree::ros_interface
