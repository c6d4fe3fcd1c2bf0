#pragma once

#include <asr_msgs/ObjectEstimateList.h>
#include <asr_msgs/RecordConfiguration.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <memory>
#include <mutex>
#include <string>

#include "asr_ism/latest_estimates.hpp"
#include "asr_ism/ros/estimate_intake.hpp"
#include "asr_ism/sqlite/demonstration_writer.hpp"

namespace asr_ism::ros_interface {

/// The recorder node: writes object configurations into a demonstration file in the original
/// ASR schema, appending to an existing file and never changing what is there; each
/// configuration is one transaction, so a kill loses at most the one being written.
/// Parameters (private): demonstration_file and scene (required), fixed_frame (map), mode:
/// "service" (record on record_configuration calls only), "interval" (the latest estimate of
/// every object seen within estimate_timeout, every `interval` seconds) or "message" (every
/// ObjectEstimateList received on `objects` as one configuration, e.g. from a replay or a bag);
/// interval (s, 1), estimate_timeout (s, 2). The service works in every mode. Counters, latched:
/// ~recorded_sets and ~rejected_estimates.
class RecorderNode {
 public:
  /// Reads and checks the parameters and opens the file: throws InputError naming them.
  RecorderNode(ros::NodeHandle node, ros::NodeHandle private_node);

 private:
  bool recordService(asr_msgs::RecordConfiguration::Request& request,
                     asr_msgs::RecordConfiguration::Response& response);
  // The topic and timer callbacks guard what they call (callback_guard.hpp).
  void receive(const asr_msgs::ObjectEstimateList& message);
  void store(const asr_msgs::ObjectEstimateList& message);
  void tick(const ros::TimerEvent& event);
  void recordLatest();
  /// Appends one configuration; returns its set id. Throws InputError.
  std::int64_t record(const std::string& scene, const Configuration& configuration);
  void publishCounters();

  ros::NodeHandle node_;
  ros::NodeHandle private_node_;
  std::string scene_;
  std::string mode_;
  double estimate_timeout_ = 2.0;
  tf2_ros::Buffer buffer_;
  tf2_ros::TransformListener listener_;
  std::mutex mutex_;
  EstimateIntake intake_;
  LatestEstimates latest_;
  std::unique_ptr<sqlite::DemonstrationWriter> writer_;
  std::size_t recorded_ = 0;
  ros::Publisher recorded_publisher_;
  ros::Publisher rejected_publisher_;
  ros::Subscriber subscriber_;
  ros::ServiceServer service_;
  ros::Timer timer_;
};

}  // namespace asr_ism::ros_interface
