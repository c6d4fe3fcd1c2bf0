#pragma once

#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>

#include "asr_robot_model/frustum.hpp"
#include "asr_state_machine/world_model.hpp"

namespace asr_state_machine::ros_interface {

/// rviz markers of the search so far, in `header`'s frame (map); opens with DELETEALL.
/// "path": the camera's way from view to view, drawn on the floor; "views": each view taken as
/// its frustum (grey, the newest yellow); "found": a box per found object with its name
/// ("found_names").
visualization_msgs::MarkerArray searchMarkers(const WorldModel& world,
                                              const asr_robot_model::Frustum& frustum,
                                              const std_msgs::Header& header);

}  // namespace asr_state_machine::ros_interface
