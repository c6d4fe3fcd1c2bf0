#include "asr_robot_model/ros/apriltag_detector_node.hpp"

#include <std_msgs/UInt64.h>
#include <tf2_eigen/tf2_eigen.h>

#include <chrono>

#include "asr_common/input_error.hpp"
#include "asr_common/ros/callback_guard.hpp"
#include "asr_common/ros/node_parameters.hpp"
#include "asr_common/ros/object_estimate_message.hpp"
#include "asr_common/ros/queue_sizes.hpp"
#include "asr_robot_model/ros/camera_messages.hpp"

namespace asr_robot_model::ros_interface {
namespace {

using namespace asr_common::ros_interface;

TagDetectorSettings detectorParameters(const ros::NodeHandle& node) {
  const TagDetectorSettings defaults;
  TagDetectorSettings settings;
  settings.decimate = numberParameter(node, "decimate", defaults.decimate, 1.0, 8.0);
  settings.threads = static_cast<int>(integerParameter(node, "threads", defaults.threads, 1, 64));
  settings.max_hamming =
      static_cast<int>(integerParameter(node, "max_hamming", defaults.max_hamming, 0, 2));
  settings.min_decision_margin =
      numberParameter(node, "min_decision_margin", defaults.min_decision_margin, 0.0, 1e6);
  settings.max_reprojection_px =
      numberParameter(node, "max_reprojection_px", defaults.max_reprojection_px, 1e-6, 1e3);
  return settings;
}

asr_msgs::ObjectEstimate estimateMessage(const ObjectDetection& object,
                                         const std_msgs::Header& header) {
  asr_msgs::ObjectEstimate message = toEstimateMessage({object.key, object.pose}, header);
  for (int row = 0; row < 6; ++row)
    for (int column = 0; column < 6; ++column)
      message.pose.covariance[6 * row + column] = object.covariance(row, column);
  return message;
}

/// A (x, y, z, rotation) covariance seen from a frame turned by `rotation`.
boost::array<double, 36> rotatedCovariance(const boost::array<double, 36>& covariance,
                                           const Eigen::Matrix3d& rotation) {
  Eigen::Matrix<double, 6, 6> turn = Eigen::Matrix<double, 6, 6>::Zero();
  turn.block<3, 3>(0, 0) = turn.block<3, 3>(3, 3) = rotation;
  const Eigen::Matrix<double, 6, 6, Eigen::RowMajor> turned =
      turn * Eigen::Map<const Eigen::Matrix<double, 6, 6, Eigen::RowMajor>>(covariance.data()) *
      turn.transpose();
  boost::array<double, 36> result;
  std::copy_n(turned.data(), 36, result.begin());
  return result;
}

}  // namespace

ApriltagDetectorNode::ApriltagDetectorNode(ros::NodeHandle node, ros::NodeHandle private_node)
    : transport_(node), tf_listener_(tf_buffer_) {
  const std::string tag_map =
      optionalParameter<std::string>(private_node, "tag_map", defaultTagMap());
  detector_ = std::make_unique<TagDetector>(loadTagMap(tag_map), detectorParameters(private_node));
  response_frame_ = optionalParameter<std::string>(private_node, "response_frame", "map");
  checkParameter(private_node, "response_frame", !response_frame_.empty(), "a frame name");
  image_timeout_ = numberParameter(private_node, "image_timeout", 3.0, 0.0, 3600.0);
  objects_ = node.advertise<asr_msgs::ObjectEstimateList>("objects", kResultQueue);
  unknown_tags_topic_ =
      private_node.advertise<std_msgs::UInt64>("unknown_tags", kLatchedQueue, true);
  std_msgs::UInt64 none;
  unknown_tags_topic_.publish(none);
  camera_info_ = node.subscribe("camera_info", 1, &ApriltagDetectorNode::onCameraInfo, this);
  image_ = transport_.subscribe("image", 1, &ApriltagDetectorNode::onImage, this);
  detect_objects_ = node.advertiseService("detect_objects", &ApriltagDetectorNode::detect, this);
}

void ApriltagDetectorNode::onCameraInfo(const sensor_msgs::CameraInfoConstPtr& message) {
  guardCallback("apriltag_detector: camera_info", [&] {
    const CameraIntrinsics camera = fromCameraInfoMessage(*message);
    std::lock_guard<std::mutex> lock(mutex_);
    camera_ = camera;
  });
}

void ApriltagDetectorNode::onImage(const sensor_msgs::ImageConstPtr& message) {
  guardCallback("apriltag_detector: image", [&] {
    std::unique_lock<std::mutex> lock(mutex_);
    if (!camera_) {
      ROS_WARN_THROTTLE(5.0, "apriltag_detector: no CameraInfo received on %s yet: image ignored",
                        camera_info_.getTopic().c_str());
      return;
    }
    bool converted = false;
    const GreyImage image = greyFromImageMessage(*message, converted);
    if (converted)
      ROS_WARN_THROTTLE(30.0, "apriltag_detector: images in encoding '%s' are converted to mono8",
                        message->encoding.c_str());
    if (image.width != camera_->width || image.height != camera_->height)
      throw asr_common::InputError("the image is " + std::to_string(image.width) + " x " +
                                   std::to_string(image.height) + " but the CameraInfo says " +
                                   std::to_string(camera_->width) + " x " +
                                   std::to_string(camera_->height));
    const auto start = std::chrono::steady_clock::now();
    const TagDetections found = detector_->detect(image, *camera_);
    latest_seconds_ =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!found.unknown_ids.empty()) {
      unknown_tags_ += found.unknown_ids.size();
      std_msgs::UInt64 count;
      count.data = unknown_tags_;
      unknown_tags_topic_.publish(count);
      ROS_DEBUG("apriltag_detector: %zu tag(s) not in the tag map ignored",
                found.unknown_ids.size());
    }
    asr_msgs::ObjectEstimateList all, requested;
    all.header = requested.header = message->header;
    for (const ObjectDetection& object : found.objects) {
      all.objects.push_back(estimateMessage(object, message->header));
      if (types_.empty() || types_.count(object.key.type))
        requested.objects.push_back(all.objects.back());
    }
    latest_ = all;
    ++images_done_;
    objects_.publish(requested);
    lock.unlock();
    image_done_.notify_all();
  });
}

bool ApriltagDetectorNode::detect(asr_msgs::DetectObjects::Request& request,
                                  asr_msgs::DetectObjects::Response& response) {
  for (const std::string& type : request.types)
    if (type.empty()) {
      ROS_WARN("apriltag_detector: detect_objects: a requested type is empty");
      return false;
    }
  std::unique_lock<std::mutex> lock(mutex_);
  types_ = {request.types.begin(), request.types.end()};
  // The first image done after the call may have been taken before it; the second was not.
  const std::uint64_t wanted = images_done_ + 2;
  if (!image_done_.wait_for(lock, std::chrono::duration<double>(image_timeout_),
                            [&] { return images_done_ >= wanted; })) {
    ROS_WARN(
        "apriltag_detector: detect_objects: no new image within %.1f s (is the camera "
        "publishing on %s?)",
        image_timeout_, image_.getTopic().c_str());
    return false;
  }
  const asr_msgs::ObjectEstimateList latest = *latest_;
  const std::set<std::string> types = types_;
  const double seconds = latest_seconds_;
  lock.unlock();
  Eigen::Isometry3d to_response;
  try {
    to_response = tf2::transformToEigen(tf_buffer_.lookupTransform(
        response_frame_, latest.header.frame_id, latest.header.stamp, ros::Duration(1.0)));
  } catch (const tf2::TransformException& error) {
    ROS_WARN("apriltag_detector: detect_objects: no transform from %s to %s: %s",
             latest.header.frame_id.c_str(), response_frame_.c_str(), error.what());
    return false;
  }
  const asr_common::Pose frame(to_response.translation(),
                               Eigen::Quaterniond(to_response.rotation()));
  response.estimates.header = latest.header;
  response.estimates.header.frame_id = response_frame_;
  for (const asr_msgs::ObjectEstimate& estimate : latest.objects) {
    if (!types.empty() && !types.count(estimate.type))
      continue;
    asr_common::ObjectEstimate moved = fromEstimateMessage(estimate);
    moved.pose = asr_common::compose(frame, moved.pose);
    asr_msgs::ObjectEstimate message = toEstimateMessage(moved, response.estimates.header);
    message.pose.covariance = rotatedCovariance(estimate.pose.covariance, to_response.rotation());
    response.estimates.objects.push_back(message);
  }
  response.seconds = seconds;
  return true;
}

}  // namespace asr_robot_model::ros_interface
