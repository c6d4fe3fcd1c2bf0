#pragma once

#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>

#include "asr_ism/demonstration.hpp"

namespace asr_ism::ros_interface {

/// rviz markers of a demonstration: a DELETEALL first, then per object its trajectory as a
/// LINE_STRIP (broken where the object was not seen) and a small sphere at its last pose, one
/// colour per object. Namespace: the scene's name.
visualization_msgs::MarkerArray demonstrationMarkers(const Demonstration& demonstration,
                                                     const std_msgs::Header& header);

}  // namespace asr_ism::ros_interface
