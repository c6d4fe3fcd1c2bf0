#include "asr_robot_model/ros/camera_sim_node.hpp"

#include "asr_common/ros/callback_guard.hpp"
#include "asr_common/ros/node_parameters.hpp"
#include "asr_robot_model/forward_kinematics.hpp"
#include "asr_robot_model/ros/camera_messages.hpp"
#include "asr_robot_model/ros/robot_state_message.hpp"

namespace asr_robot_model::ros_interface {
namespace {

using namespace asr_common::ros_interface;

CameraSimSettings cameraParameters(const ros::NodeHandle& node) {
  const CameraSimSettings defaults;
  CameraSimSettings settings;
  settings.camera = CameraIntrinsics::fromHorizontalFov(
      static_cast<int>(integerParameter(node, "width", defaults.camera.width, 1, 10000)),
      static_cast<int>(integerParameter(node, "height", defaults.camera.height, 1, 10000)),
      numberParameter(node, "horizontal_fov", M_PI / 3.0, 1e-3, M_PI - 1e-3));
  settings.noise_sigma = numberParameter(node, "noise_sigma", defaults.noise_sigma, 0.0, 127.0);
  settings.blur_sigma = numberParameter(node, "blur_sigma", defaults.blur_sigma, 0.0, 19.0);
  settings.occlusion = optionalParameter<bool>(node, "occlusion", defaults.occlusion);
  return settings;
}

}  // namespace

CameraSimNode::CameraSimNode(ros::NodeHandle node, ros::NodeHandle private_node)
    : setup_(loadSimulationSetup(private_node)), transport_(node) {
  const std::string tag_map =
      optionalParameter<std::string>(private_node, "tag_map", defaultTagMap());
  camera_ = std::make_unique<TagCameraSim>(setup_.world, loadTagMap(tag_map),
                                           cameraParameters(private_node));
  seed_ = static_cast<unsigned>(integerParameter(private_node, "seed", 1, 0, 4294967295LL));
  const double rate = numberParameter(private_node, "rate", 5.0, 0.01, 1000.0);
  publisher_ = transport_.advertiseCamera("camera/image_raw", 1);
  robot_state_ = node.subscribe("robot_state", 1, &CameraSimNode::onState, this);
  timer_ = node.createWallTimer(ros::WallDuration(1.0 / rate), &CameraSimNode::publishFrame, this);
}

void CameraSimNode::onState(const asr_msgs::RobotStateConstPtr& message) {
  state_ = *message;
}

void CameraSimNode::publishFrame(const ros::WallTimerEvent&) {
  guardCallback("camera_sim: frame", [&] {
    if (!state_) {
      ROS_WARN_THROTTLE(10.0, "camera_sim: no robot_state received yet: nothing rendered");
      return;
    }
    const ros::Time now = ros::Time::now();
    if (!rendered_state_ || *rendered_state_ != *state_ || frame_.header.stamp != now) {
      std_msgs::Header header;
      header.stamp = now;
      header.frame_id = kCameraFrame;
      // The noise of a frame follows from the seed and the simulated time alone.
      const auto nanoseconds = now.toNSec();
      const unsigned seed = seed_ ^ static_cast<unsigned>(nanoseconds ^ (nanoseconds >> 32));
      frame_ = toImageMessage(
          camera_->render(cameraPose(setup_.robot, fromStateMessage(*state_)), seed), header);
      rendered_state_ = state_;
    }
    publisher_.publish(frame_, toCameraInfoMessage(camera_->settings().camera, frame_.header));
  });
}

}  // namespace asr_robot_model::ros_interface
