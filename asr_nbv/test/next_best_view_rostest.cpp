// The next_best_view node end to end (rostest, next_best_view.launch in the shipped kitchen):
// hypotheses set from clouds, the next best view equal to the library's for the same input, the
// update after that view leaving nothing to see there, rating, removing and reset; bad input
// (NaN poses, unknown types, another frame, a NaN camera, empty clouds) answered without
// stopping the node; the markers rviz shows.
#include <asr_msgs/GetNextBestView.h>
#include <asr_msgs/RateViews.h>
#include <asr_msgs/RemoveNbvObjects.h>
#include <asr_msgs/ResetNbvHypotheses.h>
#include <asr_msgs/SetNbvHypotheses.h>
#include <asr_msgs/UpdateNbvHypotheses.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <visualization_msgs/MarkerArray.h>

#include <cmath>
#include <limits>
#include <random>
#include <set>

#include "asr_common/ros/object_estimate_message.hpp"
#include "asr_common/testing/rostest_support.hpp"
#include "asr_nbv/next_best_view_planner.hpp"
#include "asr_nbv/ros/nbv_messages.hpp"
#include "asr_robot_model/forward_kinematics.hpp"
#include "asr_robot_model/ros/robot_state_message.hpp"
#include "asr_robot_model/shipped_files.hpp"

namespace asr_nbv {
namespace {

using asr_common::testing::waitFor;
using asr_robot_model::ros_interface::fromStateMessage;
using asr_robot_model::ros_interface::toStateMessage;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

geometry_msgs::Pose poseMessage(double x, double y, double z, double yaw) {
  return asr_common::ros_interface::toPoseMessage(
      asr_common::Pose(Eigen::Vector3d(x, y, z),
                       Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()))));
}

// Cups scattered on the kitchen's table and coffee boxes on its counter, one NaN pose, and a
// type the catalogue does not know.
asr_msgs::PredictedPoseCloud kitchenCloud() {
  asr_msgs::PredictedPoseCloud cloud;
  cloud.header.frame_id = "map";
  cloud.scene = "breakfast";
  std::mt19937 random(7);
  std::uniform_real_distribution<double> spread(-0.15, 0.15), yaw(-M_PI, M_PI);
  asr_msgs::PredictedObjectPoses cup, coffee, unknown;
  cup.type = "Cup";
  cup.instance_id = "0";
  coffee.type = "CoffeeBox";
  coffee.instance_id = "0";
  unknown.type = "Teapot";
  unknown.instance_id = "1";
  for (int i = 0; i < 40; ++i) {
    cup.poses.push_back(poseMessage(2.9 + spread(random), 2.5 + spread(random), 0.77, yaw(random)));
    coffee.poses.push_back(poseMessage(1.6 + spread(random), 4.6, 1.0, yaw(random)));
  }
  unknown.poses.push_back(poseMessage(3.2, 2.6, 0.8, 0.0));
  geometry_msgs::Pose broken = poseMessage(3.0, 2.5, 0.77, 0.0);
  broken.position.y = kNaN;
  cup.poses.push_back(broken);
  cloud.objects = {cup, coffee, unknown};
  return cloud;
}

class NextBestViewNodeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    markers_ = handle_.subscribe<visualization_msgs::MarkerArray>(
        "nbv_markers", 10, [this](const visualization_msgs::MarkerArrayConstPtr& m) {
          markers_seen_ = *m;
          ++marker_messages_;
        });
    for (ros::ServiceClient* client : {&set_, &next_, &update_, &rate_, &remove_, &reset_})
      ASSERT_TRUE(client->waitForExistence(ros::Duration(60))) << client->getService();
  }

  asr_msgs::SetNbvHypotheses::Response setClouds(
      const std::vector<asr_msgs::PredictedPoseCloud>& clouds,
      const std::vector<asr_msgs::VisitedView>& visited = {}) {
    asr_msgs::SetNbvHypotheses call;
    call.request.clouds = clouds;
    call.request.visited = visited;
    EXPECT_TRUE(set_.call(call));
    return call.response;
  }

  asr_msgs::GetNextBestView::Response plan(const asr_robot_model::RobotState& from) {
    asr_msgs::GetNextBestView call;
    call.request.current = toStateMessage(from);
    EXPECT_TRUE(next_.call(call));
    return call.response;
  }

  // The view's rating from `from`, its types given (none: the best subset).
  asr_msgs::RateViews::Response rate(const asr_msgs::CameraView& view,
                                     const asr_robot_model::RobotState& from, bool with_types) {
    asr_msgs::RateViews call;
    call.request.current = toStateMessage(from);
    asr_msgs::VisitedView given;
    given.camera = view.camera;
    if (with_types)
      given.types = view.types;
    call.request.views = {given};
    EXPECT_TRUE(rate_.call(call));
    return call.response;
  }

  // Whether the latest markers hold namespace `ns`.
  bool markersHold(const std::string& ns) const {
    for (const auto& marker : markers_seen_.markers)
      if (marker.ns == ns)
        return true;
    return false;
  }

  ros::NodeHandle handle_;
  ros::ServiceClient set_ = handle_.serviceClient<asr_msgs::SetNbvHypotheses>("set_nbv_hypotheses");
  ros::ServiceClient next_ = handle_.serviceClient<asr_msgs::GetNextBestView>("get_next_best_view");
  ros::ServiceClient update_ =
      handle_.serviceClient<asr_msgs::UpdateNbvHypotheses>("update_nbv_hypotheses");
  ros::ServiceClient rate_ = handle_.serviceClient<asr_msgs::RateViews>("rate_views");
  ros::ServiceClient remove_ =
      handle_.serviceClient<asr_msgs::RemoveNbvObjects>("remove_nbv_objects");
  ros::ServiceClient reset_ =
      handle_.serviceClient<asr_msgs::ResetNbvHypotheses>("reset_nbv_hypotheses");
  ros::Subscriber markers_;
  visualization_msgs::MarkerArray markers_seen_;
  int marker_messages_ = 0;
  const asr_robot_model::RobotState start_{1.6, 2.5, 0.0, 0.0, -0.5};
};

TEST_F(NextBestViewNodeTest, RoundTripOfASearch) {
  const asr_msgs::SetNbvHypotheses::Response set = setClouds({kitchenCloud()});
  EXPECT_EQ(set.message, "");
  EXPECT_EQ(set.hypotheses, 81u);  // 40 cups, 40 coffee boxes, 1 teapot; the NaN pose rejected
  EXPECT_EQ(set.counting, 81u);
  EXPECT_EQ(set.rejected_poses, 1u);
  bool teapot_named = false;
  for (const std::string& warning : set.warnings)
    teapot_named |= warning.find("'Teapot'") != std::string::npos;
  EXPECT_TRUE(teapot_named) << "no warning names the unknown type";

  // The node answers what the library answers for the same world, parameters and seed.
  const asr_msgs::GetNextBestView::Response best = plan(start_);
  ASSERT_EQ(best.message, "");
  ASSERT_TRUE(best.found);
  const NbvParameters parameters = loadNbvParameters(defaultNbvParameters());
  const asr_robot_model::RobotDescription robot =
      asr_robot_model::loadRobotDescription(asr_robot_model::defaultRobotUrdf());
  const asr_robot_model::ObjectCatalogue catalogue =
      asr_robot_model::loadObjectCatalogue(asr_robot_model::defaultObjectCatalogue());
  const asr_robot_model::World world = asr_robot_model::loadWorld(
      asr_robot_model::shippedFile("config/worlds/kitchen.yaml"), catalogue);
  const asr_robot_model::WorldMap map(world, parameters.occlusion_resolution, robot.base_radius);
  const NextBestViewPlanner planner(robot, world, map, parameters, nullptr, 3);
  const HypothesisSet library(ros_interface::fromCloudMessages({kitchenCloud()}, "map"), catalogue);
  const PlannedView expected = planner.plan(library, start_);
  ASSERT_TRUE(expected.found);
  EXPECT_NEAR(best.view.camera.position.x, expected.camera.position.x(), 1e-9);
  EXPECT_NEAR(best.view.camera.position.y, expected.camera.position.y(), 1e-9);
  EXPECT_NEAR(best.view.camera.position.z, expected.camera.position.z(), 1e-9);
  EXPECT_NEAR(best.rating, expected.rating, 1e-12);
  EXPECT_EQ(best.view.types, expected.types);
  EXPECT_EQ(best.candidates_rated, expected.candidates_rated);
  // The view is complete: the state takes the camera, the frustum is the configured one.
  const asr_common::Pose camera =
      asr_robot_model::cameraPose(robot, fromStateMessage(best.view.state));
  EXPECT_NEAR(
      (camera.position - Eigen::Vector3d(best.view.camera.position.x, best.view.camera.position.y,
                                         best.view.camera.position.z))
          .norm(),
      0.0, 1e-6);
  EXPECT_DOUBLE_EQ(best.view.frustum.far, parameters.frustum.far());
  EXPECT_DOUBLE_EQ(best.view.frustum.fovx, parameters.frustum.fovx());
  EXPECT_GT(best.utility, 0.0);
  EXPECT_GT(best.rating, 0.0);
  EXPECT_LE(best.rating, 1.0);
  EXPECT_GT(best.costs.base, 0.0);
  EXPECT_GT(best.runtime_ms, 0.0);
  EXPECT_TRUE(waitFor([&] { return markersHold("chosen_view") && markersHold("candidates"); }, 10))
      << "no chosen view and candidates on nbv_markers";
  EXPECT_TRUE(markersHold("hypotheses"));

  // Rated as given, the chosen view has the utility the planner gave it.
  const asr_msgs::RateViews::Response before = rate(best.view, start_, true);
  ASSERT_EQ(before.message, "");
  ASSERT_EQ(before.ratings.size(), 1u);
  EXPECT_TRUE(before.ratings[0].reachable) << before.ratings[0].refusal;
  EXPECT_NEAR(before.ratings[0].utility, best.utility, 1e-9);

  // After the update, that view has nothing left to see for its types.
  asr_msgs::UpdateNbvHypotheses update;
  update.request.camera = best.view.camera;
  update.request.types = best.view.types;
  ASSERT_TRUE(update_.call(update));
  EXPECT_EQ(update.response.message, "");
  EXPECT_GT(update.response.deactivated_normals, 0u);
  EXPECT_LT(update.response.counting, set.counting);
  EXPECT_EQ(rate(best.view, start_, true).ratings.at(0).utility, 0.0);
  const asr_msgs::GetNextBestView::Response second = plan(start_);
  ASSERT_TRUE(second.found);
  EXPECT_GT(std::hypot(second.view.camera.position.x - best.view.camera.position.x,
                       second.view.camera.position.y - best.view.camera.position.y) +
                (second.view.types != best.view.types ? 1.0 : 0.0),
            0.0)
      << "the same view twice";

  // Reset: every normal active again, the first view as before.
  asr_msgs::ResetNbvHypotheses reset;
  ASSERT_TRUE(reset_.call(reset));
  EXPECT_EQ(reset.response.hypotheses, 81u);
  EXPECT_NEAR(rate(best.view, start_, true).ratings.at(0).utility, best.utility, 1e-9);

  // Removing every object of the types leaves nothing to search: found = false, no error.
  asr_msgs::RemoveNbvObjects remove;
  for (const std::string& type : {"Cup", "CoffeeBox", "Teapot"}) {
    asr_msgs::ObjectKey key;
    key.type = type;
    remove.request.objects.push_back(key);
  }
  ASSERT_TRUE(remove_.call(remove));
  EXPECT_EQ(remove.response.removed, 81u);
  EXPECT_EQ(remove.response.counting, 0u);
  const asr_msgs::GetNextBestView::Response none = plan(start_);
  EXPECT_FALSE(none.found);
  EXPECT_EQ(none.message, "");
}

TEST_F(NextBestViewNodeTest, VisitedViewsAreReplayedWhenSet) {
  setClouds({kitchenCloud()});
  const asr_msgs::GetNextBestView::Response best = plan(start_);
  ASSERT_TRUE(best.found);
  asr_msgs::VisitedView visited;
  visited.camera = best.view.camera;
  visited.types = best.view.types;
  const asr_msgs::SetNbvHypotheses::Response set = setClouds({kitchenCloud()}, {visited});
  EXPECT_EQ(set.message, "");
  EXPECT_LT(set.counting, set.hypotheses);
  EXPECT_EQ(rate(best.view, start_, true).ratings.at(0).utility, 0.0);
}

TEST_F(NextBestViewNodeTest, BadInputIsAnsweredAndTheNodeKeepsServing) {
  // An empty cloud: nothing to search, no error.
  asr_msgs::PredictedPoseCloud empty;
  empty.header.frame_id = "map";
  const asr_msgs::SetNbvHypotheses::Response none = setClouds({empty});
  EXPECT_EQ(none.message, "");
  EXPECT_EQ(none.hypotheses, 0u);
  const asr_msgs::GetNextBestView::Response nothing = plan(start_);
  EXPECT_FALSE(nothing.found);
  EXPECT_EQ(nothing.message, "");

  // A cloud in another frame is refused, naming the frame; the hypotheses stay as they were.
  setClouds({kitchenCloud()});
  asr_msgs::PredictedPoseCloud elsewhere = kitchenCloud();
  elsewhere.header.frame_id = "odom";
  const asr_msgs::SetNbvHypotheses::Response refused = setClouds({elsewhere});
  EXPECT_NE(refused.message.find("'odom'"), std::string::npos) << refused.message;
  asr_msgs::ResetNbvHypotheses reset;
  ASSERT_TRUE(reset_.call(reset));
  EXPECT_EQ(reset.response.hypotheses, 81u);

  // A NaN robot state and a NaN camera are named.
  asr_robot_model::RobotState broken = start_;
  broken.yaw = kNaN;
  const asr_msgs::GetNextBestView::Response bad_state = plan(broken);
  EXPECT_FALSE(bad_state.found);
  EXPECT_NE(bad_state.message.find("current robot state"), std::string::npos) << bad_state.message;
  asr_msgs::UpdateNbvHypotheses update;
  update.request.camera = poseMessage(1.0, 1.0, 1.2, 0.0);
  update.request.camera.orientation.w = kNaN;
  ASSERT_TRUE(update_.call(update));
  EXPECT_NE(update.response.message.find("camera"), std::string::npos) << update.response.message;
  asr_msgs::RemoveNbvObjects remove;
  remove.request.objects.resize(1);  // empty type
  ASSERT_TRUE(remove_.call(remove));
  EXPECT_NE(remove.response.message.find("empty type"), std::string::npos);

  // A view the head cannot take (camera on the floor) is unreachable, with the reason.
  asr_msgs::CameraView low;
  low.camera = poseMessage(1.0, 1.0, 0.0, 0.0);
  const asr_msgs::RateViews::Response unreachable = rate(low, start_, false);
  ASSERT_EQ(unreachable.ratings.size(), 1u);
  EXPECT_FALSE(unreachable.ratings[0].reachable);
  EXPECT_FALSE(unreachable.ratings[0].refusal.empty());
  EXPECT_EQ(unreachable.ratings[0].rating, 0.0);

  // Still serving, as before.
  const asr_msgs::GetNextBestView::Response after = plan(start_);
  EXPECT_TRUE(after.found);
  EXPECT_EQ(after.message, "");
}

}  // namespace
}  // namespace asr_nbv

int main(int argc, char** argv) {
  return asr_common::testing::runRostests(argc, argv, "next_best_view_rostest");
}
