#pragma once

#include <asr_msgs/SceneInstance.h>
#include <std_msgs/Header.h>

#include "asr_ism_tree/scene_instance.hpp"

namespace asr_ism_tree::ros_interface {

/// A recognised instance as a message in the frame and at the time of `header`.
asr_msgs::SceneInstance toSceneInstanceMessage(const SceneInstance& instance,
                                               const std_msgs::Header& header);

/// An instance from a message (e.g. in a prediction request), checked like any user input:
/// throws InputError naming the scene for an empty scene name, a confidence outside [0, 1] or a
/// bad pose. Objects keep their similarity, so that what the instance contains is known.
SceneInstance fromSceneInstanceMessage(const asr_msgs::SceneInstance& message);

}  // namespace asr_ism_tree::ros_interface
