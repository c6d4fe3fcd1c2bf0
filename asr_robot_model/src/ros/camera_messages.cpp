#include "asr_robot_model/ros/camera_messages.hpp"

#include <cv_bridge/cv_bridge.h>
#include <sensor_msgs/image_encodings.h>

#include "asr_common/input_error.hpp"

namespace asr_robot_model::ros_interface {

sensor_msgs::CameraInfo toCameraInfoMessage(const CameraIntrinsics& camera,
                                            const std_msgs::Header& header) {
  sensor_msgs::CameraInfo message;
  message.header = header;
  message.width = camera.width;
  message.height = camera.height;
  message.distortion_model = "plumb_bob";
  message.D = camera.distortion;
  message.D.resize(std::max<std::size_t>(message.D.size(), 5), 0.0);
  message.K = {camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1};
  message.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  message.P = {camera.fx, 0, camera.cx, 0, 0, camera.fy, camera.cy, 0, 0, 0, 1, 0};
  return message;
}

CameraIntrinsics fromCameraInfoMessage(const sensor_msgs::CameraInfo& message) {
  CameraIntrinsics camera;
  camera.width = static_cast<int>(message.width);
  camera.height = static_cast<int>(message.height);
  camera.fx = message.K[0];
  camera.cx = message.K[2];
  camera.fy = message.K[4];
  camera.cy = message.K[5];
  camera.distortion = message.D;
  const std::string what = "CameraInfo of frame '" + message.header.frame_id + "'";
  if (message.K[1] != 0.0 || message.K[3] != 0.0 || message.K[8] != 1.0)
    throw asr_common::InputError(what + ": camera_matrix: K must be [fx 0 cx; 0 fy cy; 0 0 1]");
  if (!message.distortion_model.empty() && message.distortion_model != "plumb_bob" &&
      message.distortion_model != "rational_polynomial")
    throw asr_common::InputError(what + ": distortion_model '" + message.distortion_model +
                                 "' is not plumb_bob or rational_polynomial");
  camera.check(what);
  return camera;
}

sensor_msgs::Image toImageMessage(const GreyImage& image, const std_msgs::Header& header) {
  sensor_msgs::Image message;
  message.header = header;
  message.width = image.width;
  message.height = image.height;
  message.encoding = sensor_msgs::image_encodings::MONO8;
  message.step = image.width;
  message.data = image.pixels;
  return message;
}

GreyImage greyFromImageMessage(const sensor_msgs::Image& message, bool& converted) {
  namespace encodings = sensor_msgs::image_encodings;
  converted = message.encoding != encodings::MONO8 && message.encoding != encodings::TYPE_8UC1;
  cv_bridge::CvImageConstPtr grey;
  try {
    grey =
        converted ? cv_bridge::toCvCopy(message, encodings::MONO8) : cv_bridge::toCvCopy(message);
  } catch (const cv_bridge::Exception& error) {
    throw asr_common::InputError("image encoding '" + message.encoding +
                                 "' cannot be read as grey: " + error.what());
  }
  if (grey->image.type() != CV_8UC1)
    throw asr_common::InputError("image encoding '" + message.encoding +
                                 "' did not convert to 8-bit grey");
  GreyImage image(grey->image.cols, grey->image.rows);
  for (int y = 0; y < grey->image.rows; ++y)
    std::copy_n(grey->image.ptr<std::uint8_t>(y), grey->image.cols,
                image.pixels.begin() + std::size_t(y) * image.width);
  return image;
}

}  // namespace asr_robot_model::ros_interface
