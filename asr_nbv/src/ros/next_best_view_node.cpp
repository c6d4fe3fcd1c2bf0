#include "asr_nbv/ros/next_best_view_node.hpp"

#include <visualization_msgs/MarkerArray.h>

#include <exception>

#include "asr_common/input_error.hpp"
#include "asr_common/ros/node_parameters.hpp"
#include "asr_common/ros/queue_sizes.hpp"
#include "asr_nbv/nbv_parameters.hpp"
#include "asr_nbv/ros/nbv_markers.hpp"
#include "asr_nbv/ros/nbv_messages.hpp"
#include "asr_nbv/view_rating.hpp"
#include "asr_robot_model/ros/robot_state_message.hpp"

namespace asr_nbv::ros_interface {
namespace {

using namespace asr_common::ros_interface;
using asr_robot_model::ros_interface::fromStateMessage;
using asr_robot_model::ros_interface::toStateMessage;

// Runs a service's body so that nothing it throws reaches roscpp: bad input is answered in
// `response.message`, and the call itself succeeds so the caller can read why.
template <typename Response, typename Body>
bool answer(const char* service, Response& response, Body&& body) noexcept {
  try {
    body();
  } catch (const asr_common::InputError& error) {
    response.message = error.what();
    ROS_WARN("next_best_view: %s refused: %s", service, error.what());
  } catch (const std::exception& error) {
    response.message = std::string("unexpected error: ") + error.what();
    ROS_ERROR("next_best_view: %s failed: %s", service, error.what());
  }
  return true;
}

}  // namespace

NextBestViewNode::NextBestViewNode(ros::NodeHandle node, ros::NodeHandle private_node)
    : fixed_frame_(fixedFrameParameter(private_node)) {
  const NbvParameters parameters = loadNbvParameters(
      optionalParameter<std::string>(private_node, "config", defaultNbvParameters()));
  const asr_robot_model::RobotDescription robot = asr_robot_model::loadRobotDescription(
      optionalParameter<std::string>(private_node, "urdf", asr_robot_model::defaultRobotUrdf()));
  catalogue_ = asr_robot_model::loadObjectCatalogue(optionalParameter<std::string>(
      private_node, "catalogue", asr_robot_model::defaultObjectCatalogue()));
  world_ =
      asr_robot_model::loadWorld(requiredParameter<std::string>(private_node, "world"), catalogue_);
  const auto seed =
      static_cast<unsigned>(integerParameter(private_node, "seed", 0, 0, 4294967295LL));
  const auto threads = static_cast<unsigned>(integerParameter(private_node, "threads", 0, 0, 256));
  map_ = std::make_unique<asr_robot_model::WorldMap>(world_, parameters.occlusion_resolution,
                                                     robot.base_radius);
  pool_ = std::make_unique<asr_ism::ThreadPool>(threads);
  planner_ =
      std::make_unique<NextBestViewPlanner>(robot, world_, *map_, parameters, pool_.get(), seed);

  markers_ = node.advertise<visualization_msgs::MarkerArray>("nbv_markers", kLatchedQueue, true);
  services_ = {
      node.advertiseService("set_nbv_hypotheses", &NextBestViewNode::setHypotheses, this),
      node.advertiseService("get_next_best_view", &NextBestViewNode::nextBestView, this),
      node.advertiseService("update_nbv_hypotheses", &NextBestViewNode::updateHypotheses, this),
      node.advertiseService("rate_views", &NextBestViewNode::rateViews, this),
      node.advertiseService("remove_nbv_objects", &NextBestViewNode::removeObjects, this),
      node.advertiseService("reset_nbv_hypotheses", &NextBestViewNode::resetHypotheses, this)};
  publishMarkers();
  ROS_INFO("next_best_view: ready, %u threads", pool_->threadCount());
}

bool NextBestViewNode::setHypotheses(asr_msgs::SetNbvHypotheses::Request& request,
                                     asr_msgs::SetNbvHypotheses::Response& response) {
  return answer("set_nbv_hypotheses", response, [&] {
    std::vector<VisitedView> visited;
    for (std::size_t v = 0; v < request.visited.size(); ++v)
      visited.push_back(
          fromVisitedViewMessage(request.visited[v], "visited view " + std::to_string(v)));
    // Built aside, so a refused request leaves the hypotheses as they were.
    HypothesisSet hypotheses(fromCloudMessages(request.clouds, fixed_frame_), catalogue_);
    for (const VisitedView& view : visited)
      updateAfterView(hypotheses, view.camera, view.types, planner_->parameters(), map_.get());
    hypotheses_ = std::move(hypotheses);
    last_plan_.reset();
    for (const std::string& warning : hypotheses_.warnings())
      ROS_WARN("next_best_view: %s", warning.c_str());
    response.hypotheses = static_cast<std::uint32_t>(hypotheses_.hypotheses().size());
    response.counting = static_cast<std::uint32_t>(hypotheses_.countingHypotheses());
    response.rejected_poses = static_cast<std::uint32_t>(hypotheses_.rejectedPoses());
    response.warnings = hypotheses_.warnings();
    publishMarkers();
  });
}

bool NextBestViewNode::nextBestView(asr_msgs::GetNextBestView::Request& request,
                                    asr_msgs::GetNextBestView::Response& response) {
  return answer("get_next_best_view", response, [&] {
    const ros::WallTime start = ros::WallTime::now();
    const PlannedView plan = planner_->plan(hypotheses_, fromStateMessage(request.current));
    response.runtime_ms = (ros::WallTime::now() - start).toSec() * 1000.0;
    response.found = plan.found;
    if (plan.found)
      response.view =
          toCameraViewMessage(plan.camera, plan.state, plan.types, planner_->parameters().frustum);
    response.utility = plan.utility;
    response.utility_max = plan.utility_max;
    response.rating = plan.rating;
    response.costs = toCostsMessage(plan.costs, plan.motion_seconds);
    response.candidates_rated = static_cast<std::uint32_t>(plan.candidates_rated);
    response.steps = static_cast<std::uint32_t>(plan.steps);
    last_plan_ = plan;
    publishMarkers();
  });
}

bool NextBestViewNode::updateHypotheses(asr_msgs::UpdateNbvHypotheses::Request& request,
                                        asr_msgs::UpdateNbvHypotheses::Response& response) {
  return answer("update_nbv_hypotheses", response, [&] {
    asr_msgs::VisitedView message;
    message.camera = request.camera;
    message.types = request.types;
    const VisitedView view = fromVisitedViewMessage(message, "the view");
    response.deactivated_normals = static_cast<std::uint32_t>(
        updateAfterView(hypotheses_, view.camera, view.types, planner_->parameters(), map_.get()));
    response.counting = static_cast<std::uint32_t>(hypotheses_.countingHypotheses());
    // The last plan stays on display: what the view just taken has deactivated shows in it.
    publishMarkers();
  });
}

bool NextBestViewNode::rateViews(asr_msgs::RateViews::Request& request,
                                 asr_msgs::RateViews::Response& response) {
  return answer("rate_views", response, [&] {
    std::vector<VisitedView> views;
    for (std::size_t v = 0; v < request.views.size(); ++v)
      views.push_back(fromVisitedViewMessage(request.views[v], "view " + std::to_string(v)));
    const RatedViews rated =
        planner_->rateViews(hypotheses_, views, fromStateMessage(request.current));
    response.utility_max = rated.utility_max;
    for (const RatedView& view : rated.views) {
      asr_msgs::ViewRating rating;
      rating.reachable = view.reachable;
      rating.refusal = view.refusal;
      rating.view =
          toCameraViewMessage(view.camera, view.state, view.types, planner_->parameters().frustum);
      rating.utility = view.utility;
      rating.rating = view.rating;
      rating.costs = toCostsMessage(view.costs, view.motion_seconds);
      response.ratings.push_back(rating);
    }
  });
}

bool NextBestViewNode::removeObjects(asr_msgs::RemoveNbvObjects::Request& request,
                                     asr_msgs::RemoveNbvObjects::Response& response) {
  return answer("remove_nbv_objects", response, [&] {
    std::vector<asr_common::ObjectKey> objects;
    for (const asr_msgs::ObjectKey& key : request.objects) {
      if (key.type.empty())
        throw asr_common::InputError("an object to remove has an empty type");
      objects.push_back({key.type, key.instance_id});
    }
    response.removed = static_cast<std::uint32_t>(hypotheses_.removeObjects(objects));
    response.counting = static_cast<std::uint32_t>(hypotheses_.countingHypotheses());
    last_plan_.reset();
    publishMarkers();
  });
}

bool NextBestViewNode::resetHypotheses(asr_msgs::ResetNbvHypotheses::Request&,
                                       asr_msgs::ResetNbvHypotheses::Response& response) {
  return answer("reset_nbv_hypotheses", response, [&] {
    hypotheses_.reset();
    response.hypotheses = static_cast<std::uint32_t>(hypotheses_.hypotheses().size());
    last_plan_.reset();
    publishMarkers();
  });
}

void NextBestViewNode::publishMarkers() {
  std_msgs::Header header;
  header.frame_id = fixed_frame_;
  header.stamp = ros::Time::now();
  markers_.publish(nbvMarkers(hypotheses_, last_plan_ ? &*last_plan_ : nullptr,
                              planner_->parameters().frustum, header));
}

}  // namespace asr_nbv::ros_interface
