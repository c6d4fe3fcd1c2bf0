#include "asr_ism/ros/replay_node.hpp"

#include <asr_msgs/ObjectEstimateList.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <filesystem>

#include "asr_common/input_error.hpp"

#include "asr_common/ros/node_parameters.hpp"
#include "asr_common/ros/object_estimate_message.hpp"
#include "asr_common/ros/queue_sizes.hpp"
#include "asr_ism/ros/demonstration_markers.hpp"
#include "asr_ism/sqlite/demonstration_reader.hpp"

namespace asr_ism::ros_interface {

using namespace asr_common::ros_interface;

ReplayNode::ReplayNode(ros::NodeHandle node, ros::NodeHandle private_node) : node_(node) {
  const auto file = requiredParameter<std::string>(private_node, "demonstration_file");
  const auto scene = requiredParameter<std::string>(private_node, "scene");
  rate_ = numberParameter(private_node, "rate", rate_, 0.001, 1000.0);
  loop_ = optionalParameter<bool>(private_node, "loop", loop_);
  wait_for_subscribers_ =
      optionalParameter<bool>(private_node, "wait_for_subscribers", wait_for_subscribers_);
  fixed_frame_ = fixedFrameParameter(private_node);
  hide_types_ = stringListParameter(private_node, "hide_types");
  demonstration_ = sqlite::readDemonstration(file, scene);
  const auto bag = optionalParameter<std::string>(private_node, "bag", "");
  if (!bag.empty()) {
    if (std::filesystem::exists(bag))
      throw asr_common::InputError("parameter " +
                                   asr_common::ros_interface::parameterName(private_node, "bag") +
                                   ": " + bag + " exists already; not overwritten");
    bag_ = std::make_unique<rosbag::Bag>(bag, rosbag::bagmode::Write);
  }
  // Large queues: a slow subscriber gets every set rather than the latest only.
  objects_publisher_ = node_.advertise<asr_msgs::ObjectEstimateList>("objects", kEveryMessageQueue);
  markers_publisher_ = node_.advertise<visualization_msgs::MarkerArray>("demonstration_markers",
                                                                        kLatchedQueue, true);
  ROS_INFO("replay_demonstration: scene '%s' from %s, %zu sets at %.1f sets/s%s", scene.c_str(),
           file.c_str(), demonstration_.stepCount(), rate_, loop_ ? ", looping" : "");
}

void ReplayNode::run() {
  std_msgs::Header header;
  header.frame_id = fixed_frame_;
  header.stamp = ros::Time::now();
  markers_publisher_.publish(demonstrationMarkers(demonstration_, header));
  // A bag gets every set without a subscriber; without one, sets published before anyone
  // listens would be lost.
  if (wait_for_subscribers_ && !bag_) {
    while (ros::ok() && objects_publisher_.getNumSubscribers() == 0)
      ros::WallDuration(0.05).sleep();
  }
  ros::Rate rate(rate_);
  do {
    for (std::size_t step = 0; step < demonstration_.stepCount() && ros::ok(); ++step) {
      asr_msgs::ObjectEstimateList list;
      list.header.stamp = ros::Time::now();
      list.header.frame_id = fixed_frame_;
      list.header.seq = static_cast<std::uint32_t>(step);
      for (const ObjectEstimate& estimate : demonstration_.configuration(step)) {
        if (std::find(hide_types_.begin(), hide_types_.end(), estimate.key.type) ==
            hide_types_.end())
          list.objects.push_back(toEstimateMessage(estimate, list.header));
      }
      objects_publisher_.publish(list);
      if (bag_)
        bag_->write("/objects", list.header.stamp, list);
      rate.sleep();
    }
  } while (loop_ && ros::ok());
  ROS_INFO("replay_demonstration: all %zu sets published%s", demonstration_.stepCount(),
           bag_ ? (" and written to " + bag_->getFileName()).c_str() : "");
  if (bag_)
    bag_->close();
}

}  // namespace asr_ism::ros_interface
