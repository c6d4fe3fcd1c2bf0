#pragma once

#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>

#include "asr_nbv/hypotheses.hpp"
#include "asr_nbv/next_best_view_planner.hpp"

// rviz markers of next_best_view (docs/next_best_view.md), all in `header`'s frame (map).
namespace asr_nbv::ros_interface {

/// Opens with DELETEALL. "hypotheses": a sphere per hypothesis, green with every normal active
/// through yellow to red with none (no longer counting). With a plan: "candidates", the views
/// rated in full, a sphere at the camera and a line along its optical axis, coloured by rating
/// from red (the lowest rated) to green (the highest); "chosen_view", the chosen camera's
/// frustum (yellow lines) and optical axis (an arrow).
visualization_msgs::MarkerArray nbvMarkers(const HypothesisSet& hypotheses, const PlannedView* plan,
                                           const asr_robot_model::Frustum& frustum,
                                           const std_msgs::Header& header);

}  // namespace asr_nbv::ros_interface
