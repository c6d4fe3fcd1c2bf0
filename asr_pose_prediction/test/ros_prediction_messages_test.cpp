// The predictor node's messages without a master: pose clouds per instance and their markers.

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "asr_pose_prediction/ros/pose_cloud_message.hpp"
#include "asr_pose_prediction/ros/prediction_markers.hpp"

namespace asr_pose_prediction::ros_interface {
namespace {

Pose at(double x) {
  return Pose(Eigen::Vector3d(x, 0, 0), Eigen::Quaterniond::Identity());
}

SceneInstance instance(double confidence, double x) {
  SceneInstance result;
  result.scene = "gedeck";
  result.confidence = confidence;
  result.pose = at(x);
  return result;
}

// Cup: 2 poses from the best instance, 1 from the second; Plate: only from the second.
std::vector<ObjectPrediction> predictions() {
  ObjectPrediction cup;
  cup.object = {"Cup", "0"};
  cup.path = {"gedeck", "gedeck_sub0"};
  cup.poses = {at(1), at(2), at(3)};
  cup.poses_per_instance = {2, 1};
  ObjectPrediction plate;
  plate.object = {"Plate", ""};
  plate.path = {"gedeck"};
  plate.poses = {at(4)};
  plate.poses_per_instance = {0, 1};
  return {cup, plate};
}

TEST(PoseCloudMessages, OneCloudPerInstanceWithItsOwnPoses) {
  std_msgs::Header header;
  header.frame_id = "map";
  const auto clouds =
      toPoseCloudMessages(predictions(), {instance(0.9, 10), instance(0.5, 20)}, header);
  ASSERT_EQ(clouds.size(), 2u);
  EXPECT_EQ(clouds[0].header.frame_id, "map");
  EXPECT_EQ(clouds[0].scene, "gedeck");
  EXPECT_DOUBLE_EQ(clouds[0].instance_confidence, 0.9);
  EXPECT_DOUBLE_EQ(clouds[0].instance_pose.position.x, 10.0);
  ASSERT_EQ(clouds[0].objects.size(), 1u);
  EXPECT_EQ(clouds[0].objects[0].type, "Cup");
  EXPECT_EQ(clouds[0].objects[0].instance_id, "0");
  EXPECT_EQ(clouds[0].objects[0].path, (std::vector<std::string>{"gedeck", "gedeck_sub0"}));
  ASSERT_EQ(clouds[0].objects[0].poses.size(), 2u);
  EXPECT_DOUBLE_EQ(clouds[0].objects[0].poses[1].position.x, 2.0);

  ASSERT_EQ(clouds[1].objects.size(), 2u);
  EXPECT_DOUBLE_EQ(clouds[1].objects[0].poses.at(0).position.x, 3.0);
  EXPECT_EQ(clouds[1].objects[1].type, "Plate");
  EXPECT_DOUBLE_EQ(clouds[1].objects[1].poses.at(0).position.x, 4.0);
}

TEST(PoseCloudMessages, AnInstanceWithoutPosesHasNoCloud) {
  auto only_second = predictions();
  only_second.erase(only_second.begin());
  const auto clouds = toPoseCloudMessages(only_second, {instance(0.9, 10), instance(0.5, 20)}, {});
  ASSERT_EQ(clouds.size(), 1u);
  EXPECT_DOUBLE_EQ(clouds[0].instance_confidence, 0.5);
}

TEST(PredictionMarkers, ClearFirstThenAnArrowPerPoseAndALabelPerObject) {
  std_msgs::Header header;
  header.frame_id = "map";
  const auto clouds =
      toPoseCloudMessages(predictions(), {instance(0.9, 10), instance(0.5, 20)}, header);
  const visualization_msgs::MarkerArray markers = predictionMarkers(clouds, {});
  ASSERT_FALSE(markers.markers.empty());
  EXPECT_EQ(markers.markers[0].action, visualization_msgs::Marker::DELETEALL);
  std::size_t arrows = 0, labels = 0;
  std::set<std::pair<std::string, int>> ids;
  for (std::size_t i = 1; i < markers.markers.size(); ++i) {
    const auto& marker = markers.markers[i];
    EXPECT_EQ(marker.header.frame_id, "map");
    EXPECT_EQ(marker.ns.rfind("gedeck/", 0), 0u) << marker.ns;
    arrows += marker.type == visualization_msgs::Marker::ARROW;
    labels += marker.type == visualization_msgs::Marker::TEXT_VIEW_FACING;
    // Markers of one namespace must not share an id, or rviz shows only the last.
    EXPECT_TRUE(ids.insert({marker.ns, marker.id}).second) << marker.ns << " " << marker.id;
  }
  EXPECT_EQ(arrows, 4u);
  EXPECT_EQ(labels, 3u);
}

TEST(PredictionMarkers, NoCloudsOnlyClears) {
  const auto markers = predictionMarkers({}, {});
  ASSERT_EQ(markers.markers.size(), 1u);
  EXPECT_EQ(markers.markers[0].action, visualization_msgs::Marker::DELETEALL);
}

TEST(PredictionMarkers, EveryArrowOfATypeHasItsColourAndTypesDiffer) {
  const auto clouds =
      toPoseCloudMessages(predictions(), {instance(0.9, 10), instance(0.5, 20)}, {});
  PredictionMarkerStyle style;
  style.alpha = 0.25;
  const visualization_msgs::MarkerArray markers = predictionMarkers(clouds, style);
  std::map<std::string, std::set<std::tuple<float, float, float, float>>> colours;
  for (const auto& marker : markers.markers) {
    if (marker.action == visualization_msgs::Marker::ADD &&
        marker.type == visualization_msgs::Marker::ARROW) {
      const std::string type = marker.ns.substr(marker.ns.find('/') + 1, 3);
      colours[type].insert({marker.color.r, marker.color.g, marker.color.b, marker.color.a});
    }
  }
  // Cup arrows come from both instances, in one colour; the plate's is another.
  ASSERT_EQ(colours.size(), 2u);
  ASSERT_EQ(colours["Cup"].size(), 1u);
  ASSERT_EQ(colours["Pla"].size(), 1u);
  EXPECT_NE(*colours["Cup"].begin(), *colours["Pla"].begin());
  EXPECT_EQ(std::get<3>(*colours["Cup"].begin()), 0.25f);
  // The same colour in every run and on every platform (an FNV-1a hash, not std::hash): Cup's
  // hue is 47 of 360 degrees, in the red-to-yellow sector (r 1, g 47/60, b 0).
  const auto cup = objectTypeColor("Cup", 1.0);
  EXPECT_FLOAT_EQ(cup.r, 1.0f);
  EXPECT_NEAR(cup.g, 47.0 / 60.0, 1e-6);
  EXPECT_FLOAT_EQ(cup.b, 0.0f);
  EXPECT_FLOAT_EQ(cup.a, 1.0f);
}

}  // namespace
}  // namespace asr_pose_prediction::ros_interface
