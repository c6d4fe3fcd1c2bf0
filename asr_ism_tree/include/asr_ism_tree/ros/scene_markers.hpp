#pragma once

#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>

#include <vector>

#include "asr_ism_tree/scene_models.hpp"

namespace asr_ism_tree::ros_interface {

/// rviz markers of scene instances: a DELETEALL first (instances no longer seen vanish), then per
/// instance a sphere above it coloured from red (confidence 0) to green (1), a text with the
/// scene's name, its confidence and object confidence, a box per object it contains, and lines for
/// its relations from each recognised ISM's reference pose to its members, one colour per ISM.
/// Namespaces are the scene names, so rviz can show or hide scenes one by one.
visualization_msgs::MarkerArray sceneInstanceMarkers(const std::vector<SceneInstance>& instances,
                                                     const SceneModels& models,
                                                     const std_msgs::Header& header);

/// Red (0) over yellow (0.5) to green (1).
std_msgs::ColorRGBA confidenceColor(double confidence);

}  // namespace asr_ism_tree::ros_interface
