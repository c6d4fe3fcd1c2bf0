#pragma once

#include <asr_msgs/DetectObjects.h>
#include <asr_msgs/ObjectEstimateList.h>
#include <image_transport/image_transport.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>

#include "asr_robot_model/tag_detector.hpp"

// apriltag_detector: objects from AprilTags in a camera's images (docs/robot.md). Subscribes to
// `image` (image_transport) and `camera_info`; for each image it publishes the objects of the
// tag map it sees on `objects` (asr_msgs/ObjectEstimateList, each pose in the image's frame, at
// its stamp, with the covariance from the reprojection error). Service detect_objects (as the
// simulated detector's) sets the types to report (empty: all) and answers with the estimates of
// an image taken after the call (the second one processed after it; up to ~image_timeout wall
// seconds, default 3), in ~response_frame (default map, through tf). Tags not in the map are
// ignored and counted on ~unknown_tags (latched, std_msgs/UInt64); images without a CameraInfo
// yet or of an encoding that is not grey are warned about (throttled) and the node goes on.
namespace asr_robot_model::ros_interface {

class ApriltagDetectorNode {
 public:
  /// Reads and checks the parameters (~tag_map, default the shipped one; ~decimate, ~threads,
  /// ~max_hamming, ~min_decision_margin, ~max_reprojection_px, ~response_frame,
  /// ~image_timeout); throws
  /// asr_common::InputError naming a bad one or the tag map's bad field.
  ApriltagDetectorNode(ros::NodeHandle node, ros::NodeHandle private_node);

 private:
  void onCameraInfo(const sensor_msgs::CameraInfoConstPtr& message);
  void onImage(const sensor_msgs::ImageConstPtr& message);
  bool detect(asr_msgs::DetectObjects::Request& request,
              asr_msgs::DetectObjects::Response& response);

  std::unique_ptr<TagDetector> detector_;
  std::string response_frame_;
  double image_timeout_ = 3.0;
  // The service waits for images while the image callback runs (two spinner threads).
  std::mutex mutex_;
  std::condition_variable image_done_;
  std::optional<CameraIntrinsics> camera_;
  std::set<std::string> types_;                         // empty: all
  std::optional<asr_msgs::ObjectEstimateList> latest_;  // every object of the latest image
  std::uint64_t images_done_ = 0;
  double latest_seconds_ = 0.0;
  std::uint64_t unknown_tags_ = 0;

  image_transport::ImageTransport transport_;
  image_transport::Subscriber image_;
  ros::Subscriber camera_info_;
  ros::Publisher objects_;
  ros::Publisher unknown_tags_topic_;
  ros::ServiceServer detect_objects_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
};

}  // namespace asr_robot_model::ros_interface
