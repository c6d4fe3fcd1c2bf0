#include "asr_ism/ros/recorder_node.hpp"

#include <std_msgs/UInt32.h>

#include "asr_common/ros/callback_guard.hpp"
#include "asr_common/ros/node_parameters.hpp"
#include "asr_common/ros/queue_sizes.hpp"

namespace asr_ism::ros_interface {

using namespace asr_common::ros_interface;

RecorderNode::RecorderNode(ros::NodeHandle node, ros::NodeHandle private_node)
    : node_(node),
      private_node_(private_node),
      listener_(buffer_),
      intake_(buffer_, fixedFrameParameter(private_node)) {
  const auto file = requiredParameter<std::string>(private_node_, "demonstration_file");
  scene_ = requiredParameter<std::string>(private_node_, "scene");
  checkParameter(private_node_, "scene", !scene_.empty(), "a scene name, not empty");
  mode_ = optionalParameter<std::string>(private_node_, "mode", "interval");
  checkParameter(private_node_, "mode",
                 mode_ == "service" || mode_ == "interval" || mode_ == "message",
                 "service, interval or message");
  const double interval = numberParameter(private_node_, "interval", 1.0, 0.001, 86400.0);
  // 0: estimates never expire.
  estimate_timeout_ = numberParameter(private_node_, "estimate_timeout", 2.0, 0.0, 1e9);
  writer_ = std::make_unique<sqlite::DemonstrationWriter>(file);

  recorded_publisher_ =
      private_node_.advertise<std_msgs::UInt32>("recorded_sets", kLatchedQueue, true);
  rejected_publisher_ =
      private_node_.advertise<std_msgs::UInt32>("rejected_estimates", kLatchedQueue, true);
  publishCounters();
  subscriber_ = node_.subscribe("objects", kEveryMessageQueue, &RecorderNode::receive, this);
  service_ = node_.advertiseService("record_configuration", &RecorderNode::recordService, this);
  if (mode_ == "interval")
    timer_ = node_.createTimer(ros::Duration(interval), &RecorderNode::tick, this);
  ROS_INFO("recorder: recording scene '%s' into %s (%s mode)", scene_.c_str(), file.c_str(),
           mode_.c_str());
}

std::int64_t RecorderNode::record(const std::string& scene, const Configuration& configuration) {
  const std::int64_t set = writer_->appendConfiguration(scene, configuration);
  ++recorded_;
  publishCounters();
  ROS_INFO_THROTTLE(5.0, "recorder: %zu configurations recorded so far", recorded_);
  return set;
}

bool RecorderNode::recordService(asr_msgs::RecordConfiguration::Request& request,
                                 asr_msgs::RecordConfiguration::Response& response) {
  std::lock_guard<std::mutex> lock(mutex_);
  Configuration configuration;
  if (request.objects.empty()) {
    configuration = latest_.current(ros::Time::now().toSec(), estimate_timeout_);
  } else {
    for (const asr_msgs::ObjectEstimate& estimate : request.objects) {
      if (auto accepted = intake_.accept(estimate))
        configuration.push_back(*accepted);
    }
    publishCounters();
  }
  if (configuration.empty()) {
    response.success = false;
    response.message = "no valid object estimate to record";
    return true;
  }
  try {
    response.set_id = record(request.scene.empty() ? scene_ : request.scene, configuration);
    response.object_count = static_cast<std::uint32_t>(configuration.size());
    response.success = true;
  } catch (const InputError& error) {
    response.success = false;
    response.message = error.what();
  }
  return true;
}

void RecorderNode::receive(const asr_msgs::ObjectEstimateList& message) {
  guardCallback("recorder: objects", [&] { store(message); });
}

void RecorderNode::store(const asr_msgs::ObjectEstimateList& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  Configuration configuration;
  for (const asr_msgs::ObjectEstimate& estimate : message.objects) {
    if (auto accepted = intake_.accept(estimate)) {
      latest_.update(*accepted, estimate.header.stamp.toSec());
      configuration.push_back(*accepted);
    }
  }
  publishCounters();
  if (mode_ != "message" || configuration.empty())
    return;
  try {
    record(scene_, configuration);
  } catch (const InputError& error) {
    ROS_WARN_THROTTLE(5.0, "recorder: configuration not recorded: %s", error.what());
  }
}

void RecorderNode::tick(const ros::TimerEvent&) {
  guardCallback("recorder: interval recording", [&] { recordLatest(); });
}

void RecorderNode::recordLatest() {
  std::lock_guard<std::mutex> lock(mutex_);
  const Configuration configuration = latest_.current(ros::Time::now().toSec(), estimate_timeout_);
  if (configuration.empty())
    return;
  try {
    record(scene_, configuration);
  } catch (const InputError& error) {
    ROS_WARN_THROTTLE(5.0, "recorder: configuration not recorded: %s", error.what());
  }
}

void RecorderNode::publishCounters() {
  std_msgs::UInt32 count;
  count.data = static_cast<std::uint32_t>(recorded_);
  recorded_publisher_.publish(count);
  count.data = static_cast<std::uint32_t>(intake_.rejectedCount());
  rejected_publisher_.publish(count);
}

}  // namespace asr_ism::ros_interface
