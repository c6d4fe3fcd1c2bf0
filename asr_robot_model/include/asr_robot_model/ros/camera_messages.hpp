#pragma once

#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

#include <string>

#include "asr_robot_model/camera_intrinsics.hpp"
#include "asr_robot_model/grey_image.hpp"

// The simulated camera's and the tag detector's images and intrinsics between the core and
// sensor_msgs.
namespace asr_robot_model::ros_interface {

sensor_msgs::CameraInfo toCameraInfoMessage(const CameraIntrinsics& camera,
                                            const std_msgs::Header& header);
/// Checked like any input: throws asr_common::InputError naming the field (K, D, width) if the
/// message cannot describe a camera.
CameraIntrinsics fromCameraInfoMessage(const sensor_msgs::CameraInfo& message);

sensor_msgs::Image toImageMessage(const GreyImage& image, const std_msgs::Header& header);
/// The image as 8-bit grey: mono8 as it is; colour and 16-bit grey converted through cv_bridge,
/// with `converted` set. Throws asr_common::InputError naming the encoding for anything cv_bridge
/// cannot convert to grey.
GreyImage greyFromImageMessage(const sensor_msgs::Image& message, bool& converted);

}  // namespace asr_robot_model::ros_interface
