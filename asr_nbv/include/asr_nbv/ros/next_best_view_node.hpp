#pragma once

#include <asr_msgs/GetNextBestView.h>
#include <asr_msgs/RateViews.h>
#include <asr_msgs/RemoveNbvObjects.h>
#include <asr_msgs/ResetNbvHypotheses.h>
#include <asr_msgs/SetNbvHypotheses.h>
#include <asr_msgs/UpdateNbvHypotheses.h>
#include <ros/ros.h>

#include <memory>
#include <optional>
#include <string>

#include "asr_ism/thread_pool.hpp"
#include "asr_nbv/hypotheses.hpp"
#include "asr_nbv/next_best_view_planner.hpp"
#include "asr_robot_model/world.hpp"
#include "asr_robot_model/world_map.hpp"

// The next_best_view node (docs/next_best_view.md): holds the hypotheses of a search and plans
// the view to move to next. Services set_nbv_hypotheses, get_next_best_view,
// update_nbv_hypotheses, rate_views, remove_nbv_objects and reset_nbv_hypotheses; latched
// nbv_markers for rviz. A bad request is answered with a message naming what is wrong (and the
// node keeps serving); it never ends the node.
namespace asr_nbv::ros_interface {

class NextBestViewNode {
 public:
  /// Reads and checks the private parameters: world (required), config (default the shipped
  /// config/next_best_view.yaml), urdf and catalogue (default the shipped ones), seed (0),
  /// threads (0: every core), fixed_frame (map). Throws asr_common::InputError naming a bad
  /// parameter or file.
  NextBestViewNode(ros::NodeHandle node, ros::NodeHandle private_node);

 private:
  bool setHypotheses(asr_msgs::SetNbvHypotheses::Request& request,
                     asr_msgs::SetNbvHypotheses::Response& response);
  bool nextBestView(asr_msgs::GetNextBestView::Request& request,
                    asr_msgs::GetNextBestView::Response& response);
  bool updateHypotheses(asr_msgs::UpdateNbvHypotheses::Request& request,
                        asr_msgs::UpdateNbvHypotheses::Response& response);
  bool rateViews(asr_msgs::RateViews::Request& request, asr_msgs::RateViews::Response& response);
  bool removeObjects(asr_msgs::RemoveNbvObjects::Request& request,
                     asr_msgs::RemoveNbvObjects::Response& response);
  bool resetHypotheses(asr_msgs::ResetNbvHypotheses::Request& request,
                       asr_msgs::ResetNbvHypotheses::Response& response);
  /// The hypotheses, and the last plan until hypotheses are set, removed or reset.
  void publishMarkers();

  std::string fixed_frame_;
  asr_robot_model::ObjectCatalogue catalogue_;
  asr_robot_model::World world_;
  std::unique_ptr<asr_robot_model::WorldMap> map_;
  std::unique_ptr<asr_ism::ThreadPool> pool_;
  std::unique_ptr<NextBestViewPlanner> planner_;
  HypothesisSet hypotheses_;
  std::optional<PlannedView> last_plan_;
  ros::Publisher markers_;
  std::vector<ros::ServiceServer> services_;
};

}  // namespace asr_nbv::ros_interface
